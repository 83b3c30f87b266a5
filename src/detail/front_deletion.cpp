// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "front_deletion.h"

#include "removal_log.h"
#include "retraction.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <memory>
#include <new>
#include <set>
#include <unordered_map>

namespace pcl_wrap::detail
{
namespace
{

/** Watches a trial's removals for one that was on the front (W, or the part of it on flagged
  * vertices) just before the trial: in a 3-dimensional complex, a triangle with fewer than two
  * tetrahedra of X, an edge with no triangle, a vertex with no edge (in lower dimensions
  * everything is on W). A removed simplex's cofaces leave in the same step or earlier (Y stays a
  * complex), so counting them among the removals tells how many it had, and once a step is over
  * only the new removals need a look. The counts live in flat arrays, tagged with the trial they
  * belong to, so a new trial starts without clearing them. */
class SurfaceWatch
{
public:
  SurfaceWatch (const SimplicialComplex& complex, const std::vector<std::uint8_t>& in_front)
    : complex_ (complex), in_front_ (in_front)
  {}

  /** Forgets the removals of the last trial. */
  void beginTrial ()
  {
    seen_ = 0;
    if (complex_.dimension () < 3)
      return;
    if (!counts_[0] || ++trial_ == MAX_TRIAL)
    {
      // calloc: a large block comes as fresh zero pages, not written here, so only the pages
      // that trials touch cost anything.
      for (int k = 0; k < 3; ++k)
        counts_[k] = Counts (static_cast<std::uint32_t*> (std::calloc (complex_.size (k) + 1, sizeof (std::uint32_t))));
      if (!counts_[0] || !counts_[1] || !counts_[2])
        throw std::bad_alloc ();
      trial_ = 1;
    }
  }

  /** Looks at the removals it has not seen; true when one of them was on the front. */
  bool reached (const std::vector<Simplex>& removed)
  {
    if (complex_.dimension () < 3)
    {
      for (; seen_ < removed.size (); ++seen_)
        if (inRegion (removed[seen_]))
          return true;
      return false;
    }
    const std::size_t first = seen_;
    for (; seen_ < removed.size (); ++seen_)
      for (int i = 0; i <= removed[seen_].dim && removed[seen_].dim > 0; ++i)
      {
        const Simplex f = complex_.facet (removed[seen_].dim, removed[seen_].id, i);
        std::uint32_t& c = counts_[f.dim][f.id];
        c = (c >> 2) == trial_ ? std::min (c + 1, (trial_ << 2) | 3) : (trial_ << 2) | 1;
      }
    for (std::size_t k = first; k < removed.size (); ++k)
    {
      const Simplex xi = removed[k];
      if (xi.dim == 3 || !inRegion (xi))
        continue;
      const std::uint32_t c = counts_[xi.dim][xi.id];
      const std::uint32_t before = (c >> 2) == trial_ ? (c & 3) : 0;
      if (before < (xi.dim == 2 ? 2u : 1u))
        return true;
    }
    return false;
  }

private:
  static constexpr std::uint32_t MAX_TRIAL = 1u << 30;

  bool inRegion (Simplex s) const
  {
    if (in_front_.empty ())
      return true;
    for (int i = 0; i <= s.dim; ++i)
      if (!in_front_[complex_.vertex (s.dim, s.id, i)])
        return false;
    return true;
  }

  const SimplicialComplex& complex_;
  const std::vector<std::uint8_t>& in_front_;
  struct Free
  {
    void operator() (std::uint32_t* p) const { std::free (p); }
  };
  using Counts = std::unique_ptr<std::uint32_t[], Free>;
  // Per simplex of dimension 0-2: (trial << 2) | its cofaces removed in that trial, at most 3.
  std::array<Counts, 3> counts_;
  std::uint32_t trial_ = 0;
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

  /** A trial reached the front: its removals are kept. */
  void committed (const SimplicialComplex& complex, const std::vector<Simplex>& removed)
  {
    ++commits_;
    for (const Simplex xi : removed)
      for (int i = 0; i <= xi.dim; ++i)
        touched_at_[complex.vertex (xi.dim, xi.id, i)] = commits_;
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
    std::size_t commits;    // commits before it, or before it was last found to hold
    std::size_t begin, end; // its removals' vertices in vertices_
  };

  std::vector<std::uint32_t> failure_of_; // per candidate: the failure that rules it out, or NONE
  std::vector<Failure> failures_;
  std::vector<std::uint32_t> vertices_;
  std::vector<std::size_t> touched_at_;   // per vertex: the last commit that removed a simplex on it
  std::vector<std::uint32_t> listed_by_;  // per vertex: the last failure that listed it
  std::size_t commits_ = 0;
};

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
  SurfaceWatch surface (complex, in_front);
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
        for (; scanned < log.trialRemovals ().size () && !reached; ++scanned)
        {
          // A cosink's last coface one dimension up leaves in the trial: look at facets only.
          const Simplex xi = log.trialRemovals ()[scanned];
          for (int i = 0; i <= xi.dim && xi.dim > 0; ++i)
          {
            const Simplex f = complex.facet (xi.dim, xi.id, i);
            if (y.principal (f))
              if (const std::uint32_t* r = rank (f))
                pending.insert (*r);
          }
        }
      }
      if (reached)
      {
        inside.committed (complex, log.trialRemovals ());
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
