// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/front_deletion.h"

#include "util/parallel_for_each.h"
#include "util/portable.h"
#include "wrap/removal_log.h"
#include "wrap/retraction.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <set>
#include <unordered_map>

namespace pcl_wrap::detail
{
namespace
{

/** Tells whether a trial removed a simplex of the front (W, or the part of it on flagged
  * vertices) as it was just before the trial: in a 3-dimensional complex, a triangle with fewer
  * than two tetrahedra, an edge with no triangle, a vertex with no edge (in lower dimensions,
  * everything). One byte per simplex says whether it is on the front; a kept trial changes the
  * coface counts of the facets of what it removed only, and a trial put back changes nothing. */
class SurfaceWatch
{
public:
  SurfaceWatch (const Subcomplex& y, const std::vector<std::uint8_t>& in_front)
    : y_ (y), complex_ (y.complex ()), in_front_ (in_front)
  {
    for (int k = 0; k <= std::min (2, complex_.dimension ()); ++k)
    {
      on_front_[k].resize (complex_.size (k));
      parallelForEach (complex_.size (k), [&] (std::size_t s) {
        on_front_[k][s] = onFront ({k, static_cast<SimplexId> (s)});
      });
    }
  }

  void beginTrial () { seen_ = 0; }

  /** Looks at the trial's removals it has not seen; true when one of them was on the front. */
  bool reached (const std::vector<Simplex>& removed)
  {
    const std::size_t first = seen_;
    seen_ = removed.size ();
    return countInParallel (seen_ - first, [&] (std::size_t i) {
             const Simplex s = removed[first + i];
             return s.dim < 3 && on_front_[s.dim][s.id] != 0;
           }) != 0;
  }

  /** A kept trial removed \a xi; called on several threads at once. */
  void kept (Simplex xi)
  {
    for (int j = 0; j <= xi.dim && xi.dim > 0; ++j)
    {
      const Simplex f = complex_.facet (xi.dim, xi.id, j);
      if (f.dim < 3 && y_.contains (f)) // facets shared by removals get the same value
        relaxedStore (&on_front_[f.dim][f.id], std::uint8_t (onFront (f)));
    }
  }

private:
  bool onFront (Simplex s) const
  {
    if (!y_.contains (s) || !inRegion (s))
      return false;
    return complex_.dimension () < 3 || y_.cofaceCount (s) < (s.dim == 2 ? 2u : 1u);
  }

  bool inRegion (Simplex s) const
  {
    if (in_front_.empty ())
      return true;
    for (int i = 0; i <= s.dim; ++i)
      if (!in_front_[complex_.vertex (s.dim, s.id, i)])
        return false;
    return true;
  }

  const Subcomplex& y_;
  const SimplicialComplex& complex_;
  const std::vector<std::uint8_t>& in_front_;
  std::array<std::vector<std::uint8_t>, 3> on_front_; // per simplex of dimension 0-2
  std::size_t seen_ = 0;
};

/** Which candidates need no trial because one that stayed inside rules them out.
  * - The trial of a candidate that such a trial removed, from the same Y, removes part of what
  *   that trial removed (a retraction removes more from less: docs/design.md §6), so it stays
  *   inside too.
  * - A trial reads only simplices with a vertex among its removals' vertices, so its outcome holds
  *   until a commit removes a simplex with one of those vertices. */
class StayedInside
{
public:
  StayedInside (std::size_t candidates, std::size_t vertices)
    : failure_of_ (candidates, NONE), touched_at_ (vertices, 0), listed_by_ (vertices, NONE)
  {}

  /** A trial stayed inside: it rules out the candidates among its removals (\a rank gives their
    * ranks, or null). */
  template <class Rank>
  void failed (const SimplicialComplex& complex, const std::vector<Simplex>& removed, const Rank& rank)
  {
    const auto id = static_cast<std::uint32_t> (failures_.size ());
    failures_.push_back ({commits_, vertices_.size (), 0});
    for (const Simplex xi : removed)
    {
      if (const std::uint32_t* r = rank (xi))
        failure_of_[*r] = id;
      for (int i = 0; i <= xi.dim; ++i)
      {
        const std::uint32_t v = complex.vertex (xi.dim, xi.id, i);
        if (listed_by_[v] != id)
          listed_by_[v] = id, vertices_.push_back (v);
      }
    }
    failures_.back ().end = vertices_.size ();
  }

  /** A trial reached the front: its removals are kept, each told to kept() if watching(). */
  void committed () { ++commits_; }
  /** Only failures before a commit read what it touched. */
  bool watching () const { return !failures_.empty (); }
  /** A kept trial removed \a xi; called on several threads at once. */
  void kept (const SimplicialComplex& complex, Simplex xi)
  {
    for (int i = 0; i <= xi.dim; ++i)
      relaxedStore (&touched_at_[complex.vertex (xi.dim, xi.id, i)], commits_);
  }

  bool ruledOut (std::size_t candidate)
  {
    if (failure_of_[candidate] == NONE)
      return false;
    Failure& f = failures_[failure_of_[candidate]];
    if (f.commits != commits_)
    {
      for (std::size_t i = f.begin; i < f.end; ++i)
        if (touched_at_[vertices_[i]] > f.commits)
        {
          failure_of_[candidate] = NONE;
          return false;
        }
      f.commits = commits_; // still holds: no need to look again before the next commit
    }
    return true;
  }

private:
  static constexpr std::uint32_t NONE = ~std::uint32_t (0);
  struct Failure
  {
    std::uint32_t commits;  // commits before it, or before it was last found to hold
    std::size_t begin, end; // its removals' vertices in vertices_
  };

  std::vector<std::uint32_t> failure_of_; // per candidate: the failure that rules it out, or NONE
  std::vector<Failure> failures_;
  std::vector<std::uint32_t> vertices_;
  std::vector<std::uint32_t> touched_at_; // per vertex: the last commit that removed a simplex on it
  std::vector<std::uint32_t> listed_by_;  // per vertex: the last failure that listed it
  std::uint32_t commits_ = 0;
};

/** The ranks (\a rank gives them, or null) of the simplices that removed[from, end) left
  * principal, found on all threads. A cosink's last coface one dimension up leaves in the trial:
  * facets suffice. */
template <class Rank>
std::vector<std::uint32_t>
uncoveredSinks (const Subcomplex& y, const std::vector<Simplex>& removed, std::size_t from, const Rank& rank)
{
  const SimplicialComplex& complex = y.complex ();
  return tbb::parallel_reduce (
      tbb::blocked_range<std::size_t> (from, removed.size (), 4096), std::vector<std::uint32_t> (),
      [&] (const tbb::blocked_range<std::size_t>& range, std::vector<std::uint32_t> found) {
        for (std::size_t k = range.begin (); k != range.end (); ++k)
          for (int i = 0; i <= removed[k].dim && removed[k].dim > 0; ++i)
          {
            const Simplex f = complex.facet (removed[k].dim, removed[k].id, i);
            if (y.principal (f))
              if (const std::uint32_t* r = rank (f))
                found.push_back (*r);
          }
        return found;
      },
      [] (std::vector<std::uint32_t> a, const std::vector<std::uint32_t>& b) {
        a.insert (a.end (), b.begin (), b.end ());
        return a;
      });
}

} // namespace

FrontDeletion
deleteExposedSinks (Subcomplex& y, const Classification& classification, const WrapFiltration& order, double delta,
                    const std::vector<std::uint8_t>& in_front, std::uint64_t order_seed)
{
  const SimplicialComplex& complex = y.complex ();
  RemovalLog log (complex);
  Retraction retraction (y, classification, &log);
  // The rank of every sink larger than delta, to find those a trial uncovers. Few simplices are
  // sinks: their one-byte class is read before the map.
  std::unordered_map<std::uint64_t, std::uint32_t> ranks;
  const auto key = [] (Simplex s) { return (std::uint64_t (s.dim) << 32) | s.id; };
  std::size_t candidates = 0;
  while (candidates < order.sinks.size () && order.sink_sizes[candidates] > delta)
  {
    ranks.emplace (key (order.sinks[candidates]), static_cast<std::uint32_t> (candidates));
    ++candidates;
  }
  const auto rank = [&] (Simplex s) -> const std::uint32_t* {
    if (classification.of (s) != SimplexClass::centered)
      return nullptr;
    const auto it = ranks.find (key (s));
    return it == ranks.end () ? nullptr : &it->second;
  };

  StayedInside inside (candidates, complex.size (0));
  SurfaceWatch surface (y, in_front);
  FrontDeletion result;
  for (bool progress = true; progress;)
  {
    progress = false;
    for (std::size_t j = 0; j < candidates; ++j)
    {
      if (!y.principal (order.sinks[j]) || inside.ruledOut (j))
        continue;
      // A trial deletes the sink, then, while its basin has not reached the surface, the larger-
      // than-delta sinks it made principal (its cosinks), largest first. All or nothing.
      log.beginTrial ();
      surface.beginTrial ();
      std::set<std::uint32_t> pending = {static_cast<std::uint32_t> (j)};
      std::size_t scanned = 0, deleted = 0;
      bool reached = false;
      while (!pending.empty () && !reached)
      {
        const Simplex sink = order.sinks[*pending.begin ()];
        pending.erase (pending.begin ());
        if (!retraction.deletePrincipal (sink))
          continue;
        ++deleted;
        retraction.retractFreed (order_seed);
        reached = surface.reached (log.trialRemovals ());
        if (!reached)
        {
          const std::vector<std::uint32_t> cosinks = uncoveredSinks (y, log.trialRemovals (), scanned, rank);
          pending.insert (cosinks.begin (), cosinks.end ());
          scanned = log.trialRemovals ().size ();
        }
      }
      if (reached)
      {
        inside.committed ();
        const std::vector<Simplex>& removed = log.trialRemovals ();
        const bool watching = inside.watching ();
        parallelForEach (removed.size (), [&] (std::size_t i) {
          if (watching)
            inside.kept (complex, removed[i]);
          surface.kept (removed[i]);
        });
        log.commitTrial ();
        result.deleted += deleted;
        progress = true;
      }
      else
      {
        inside.failed (complex, log.trialRemovals (), rank);
        log.rollbackTrial (y);
      }
    }
  }
  for (std::size_t j = 0; j < candidates; ++j)
    if (y.contains (order.sinks[j]))
      ++(y.principal (order.sinks[j]) ? result.enclosed : result.not_principal);
  return result;
}

} // namespace pcl_wrap::detail
