// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/open_sheet.h"

#include "util/distance.h"
#include "util/parallel_for_each.h"
#include "util/union_find.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

using Triangle = std::array<std::uint32_t, 3>;
constexpr std::uint32_t NONE = ~std::uint32_t (0);
/** A gap wider than this many spacings is one the sampling resolves: no triangle crosses it.
  * Within a uniformly sampled sheet, one edge of W in two thousand is longer. */
constexpr double GAP_SPACINGS = 3.5;
/** Holes bounded by more edges are not looked at for filling (the widest fillable is a few spacings). */
constexpr std::size_t MAX_HOLE_EDGES = 24;
/** A piece of the sheets with fewer points than this, beside one with at least CRUMB_OF times as
  * many, is a crumb the growth left apart: its points are brought onto the larger one by tents. */
constexpr std::size_t CRUMB_POINTS = 10, CRUMB_OF = 100;
/** Rounds of tents, each bringing on the points one tetrahedron joins to the sheets. */
constexpr int MAX_TENT_ROUNDS = 8;
/** The id of a filling triangle, which need not be a face of the complex. */
constexpr SimplexId NO_ID = ~SimplexId (0);

/** The three edge ids of triangle \a id, opposite its vertices 2, 1 and 0: edge k joins its
  * vertices k and k + 1 (mod 3) in the complex's order. */
std::array<SimplexId, 3>
edgesOf (const SimplicialComplex& complex, SimplexId id)
{
  return {complex.face (2, id, 0b011).id, complex.face (2, id, 0b110).id, complex.face (2, id, 0b101).id};
}

/** Is \a t an even permutation of its vertices in ascending order? */
bool
evenOrder (const Triangle& t)
{
  return (t[0] < t[1]) + (t[1] < t[2]) + (t[2] < t[0]) == 2;
}

std::array<double, 3>
areaNormal (const Triangle& t, const std::vector<Point3>& p)
{
  const Point3 &a = p[t[0]], &b = p[t[1]], &c = p[t[2]];
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

/** Does the oriented triangle \a t run along its edge from \a a to \a b? */
bool
runsFrom (const Triangle& t, std::uint32_t a, std::uint32_t b)
{
  return (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
}

/** An edge ab of a vertex v's link, as (a, b) with a < b, and the triangle abv of Del S. */
using LinkEdge = std::pair<std::pair<std::uint32_t, std::uint32_t>, SimplexId>;

/** The edges of \a v's link in Del S, sorted, each once. */
void
gatherLinkEdges (const Tetrahedra& tetrahedra, std::uint32_t v, Star& star, std::vector<LinkEdge>& link)
{
  const SimplicialComplex& complex = tetrahedra.complex ();
  tetrahedra.gatherStar (v, star);
  link.clear ();
  for (std::uint32_t t : star.tetrahedra ())
  {
    const int apex = tetrahedra.localIndex (t, v);
    for (int k = 1; k < 4; ++k)
    {
      // Facet i of t holds v and the two vertices other than the apex and vertex i.
      const int i = (apex + k) & 3;
      std::uint32_t ab[2], n = 0;
      for (int j = 0; j < 4; ++j)
        if (j != apex && j != i)
          ab[n++] = tetrahedra.vertex (t, j);
      link.push_back ({{std::min (ab[0], ab[1]), std::max (ab[0], ab[1])}, complex.facet (3, t, i).id});
    }
  }
  std::sort (link.begin (), link.end ());
  link.erase (std::unique (link.begin (), link.end ()), link.end ());
}

/** The growth of the sheets: the candidate triangles and the region grown from them. */
class SheetGrowth
{
public:
  SheetGrowth (const Tetrahedra& tetrahedra, const Boundary& w, const std::vector<Point3>& positions)
    : complex_ (tetrahedra.complex ()),
      positions_ (positions),
      edge_count_ (complex_.size (1), 0),
      edge_forward_ (complex_.size (1), 0),
      on_ (complex_.numVertices (), 0),
      open_edges_ (complex_.numVertices (), 0)
  {
    measureSpacing (w);
    std::vector<std::uint8_t> across_gap (w.triangle_ids.size ());
    parallelForEach (across_gap.size (),
                     [&] (std::size_t i) { across_gap[i] = spansGap (complex_.vertices (2, w.triangle_ids[i])); });
    for (std::size_t i = 0; i < across_gap.size (); ++i)
      if (!across_gap[i])
        candidates_.push_back (w.triangle_ids[i]);
    extra_from_ = static_cast<std::uint32_t> (candidates_.size ());
    addTrianglesAroundDanglingEdges (tetrahedra, w);
    indexCandidates ();
  }

  /** Per candidate what the growth reads of it, and per edge the candidates on it, as offsets
    * into one array; the new candidates not placed. Built anew each time, not grown: a grown
    * array is copied, and the copy is this stage's peak of memory. */
  void indexCandidates ()
  {
    std::vector<Candidate> ().swap (about_);
    std::vector<std::uint32_t> ().swap (edge_candidates_);
    about_.resize (candidates_.size ());
    parallelForEach (candidates_.size (), [&] (std::size_t i) {
      Candidate& c = about_[i];
      const std::uint32_t* v = complex_.vertices (2, candidates_[i]);
      c.v = {v[0], v[1], v[2]};
      c.e = edgesOf (complex_, candidates_[i]);
      double longest = 0;
      for (int k = 0; k < 3; ++k)
        longest = std::max (longest, squaredDistance (positions_[v[k]], positions_[v[(k + 1) % 3]]));
      c.size = static_cast<float> (longest);
    });
    edge_start_.assign (complex_.size (1) + 1, 0);
    for (const Candidate& c : about_)
      for (SimplexId e : c.e)
        ++edge_start_[e + 1];
    for (std::size_t e = 0; e + 1 < edge_start_.size (); ++e)
      edge_start_[e + 1] += edge_start_[e];
    edge_candidates_.resize (edge_start_.back ());
    std::vector<std::uint32_t> at (edge_start_.begin (), edge_start_.end () - 1);
    for (std::uint32_t c = 0; c < about_.size (); ++c)
      for (SimplexId e : about_[c].e)
        edge_candidates_[at[e]++] = c;
    placed_.resize (candidates_.size (), NONE);
  }

  /** Places what the queues hold. */
  void drain ()
  {
    while (!notches_.empty () || !queue_.empty ())
    {
      Entry e;
      if (!notches_.empty ())
      {
        e = notches_.back ();
        notches_.pop_back ();
      }
      else
        e = queue_.pop ();
      if (placed_[e.candidate] == NONE)
        tryPlace (e.candidate, e.edge);
    }
  }

  /** Closes the cracks between fronts that face each other across less than a gap (X, being
    * contractible, cuts a ring-shaped layer, an annulus or a terrain around a pond, somewhere, and
    * W's triangles leave the cut open) and reaches the points inside X's thick parts, which W
    * passes over. The Delaunay triangles whose three points are each on the front or on no sheet
    * yet, and that span no gap, become candidates, and the growth goes on from the front. */
  void closeCracks (const Tetrahedra& tetrahedra)
  {
    lendSpacing (tetrahedra);
    std::vector<std::uint8_t> listed (complex_.size (2), 0);
    for (SimplexId id : candidates_)
      listed[id] = 1;
    // On the front, or on no sheet yet (a point inside X's thick parts).
    const auto open = [&] (std::uint32_t v) { return open_edges_[v] > 0 || !on_[v]; };
    // Facet i of tetrahedron t, if it closes a crack and t is the lower of its two tetrahedra.
    const auto crack = [&] (std::uint32_t t, int i) {
      for (int k = 1; k < 4; ++k)
        if (!open (tetrahedra.vertex (t, (i + k) & 3)))
          return NO_ID;
      const std::uint32_t u = tetrahedra.neighbour (t, i);
      const SimplexId f = complex_.facet (3, t, i).id;
      return (u != OUTSIDE_HULL && u < t) || listed[f] || spansGap (complex_.vertices (2, f)) ? NO_ID : f;
    };
    const std::size_t before = candidates_.size ();
    crack_from_ = static_cast<std::uint32_t> (before);
    fillInOrder (
        tetrahedra.size (),
        [&] (std::size_t t) {
          std::size_t n = 0;
          for (int i = 0; i < 4; ++i)
            n += crack (static_cast<std::uint32_t> (t), i) != NO_ID;
          return n;
        },
        [&] (std::size_t total) { candidates_.resize (before + total); },
        [&] (std::size_t t, std::size_t at) {
          for (int i = 0; i < 4; ++i)
            if (const SimplexId f = crack (static_cast<std::uint32_t> (t), i); f != NO_ID)
              candidates_[before + at++] = f;
          return at;
        });
    std::vector<std::uint8_t> ().swap (listed);
    if (candidates_.size () == before)
      return;
    forgetQueues ();
    indexCandidates ();
    for (std::size_t c = before; c < candidates_.size (); ++c)
      for (SimplexId e : about_[c].e)
        if (edge_count_[e] == 1)
          queueAround (e);
    drain ();
  }

  /** Gives each point the growth has not reached and that has no spacing (it is on no edge of W:
    * inside X's thick parts, such as the corner X fills between a wall and the ground) the median
    * spacing of the points around it, inwards from those that have one. */
  void lendSpacing (const Tetrahedra& tetrahedra)
  {
    std::vector<std::uint32_t> missing;
    for (std::uint32_t v = 0; v < complex_.numVertices (); ++v)
      if (!on_[v] && spacing_[v] == 0 && tetrahedra.tetrahedronOf (v) != NO_TETRAHEDRON)
        missing.push_back (v);
    Star star;
    std::vector<double> around;
    std::vector<std::pair<std::uint32_t, double>> lent;
    while (!missing.empty ())
    {
      lent.clear ();
      for (std::uint32_t v : missing)
      {
        tetrahedra.gatherStar (v, star);
        around.clear ();
        for (std::uint32_t t : star.tetrahedra ())
          for (int k = 0; k < 4; ++k)
            if (const std::uint32_t u = tetrahedra.vertex (t, k); spacing_[u] > 0)
              around.push_back (spacing_[u]);
        if (around.empty ())
          continue;
        const auto middle = around.begin () + std::ptrdiff_t (around.size ()) / 2;
        std::nth_element (around.begin (), middle, around.end ());
        lent.push_back ({v, *middle});
      }
      if (lent.empty ())
        return;
      for (const auto& [v, spacing] : lent)
        spacing_[v] = spacing;
      missing.erase (std::remove_if (missing.begin (), missing.end (),
                                     [&] (std::uint32_t v) { return spacing_[v] > 0; }),
                     missing.end ());
    }
  }

  /** Grows sheets from every W triangle not reached yet whose points are all new. */
  void grow ()
  {
    for (std::uint32_t seed = 0; seed < extra_from_; ++seed)
    {
      const std::uint32_t* v = about_[seed].v.data ();
      if (placed_[seed] != NONE || on_[v[0]] || on_[v[1]] || on_[v[2]])
        continue;
      place (seed, {v[0], v[1], v[2]});
      drain ();
    }
  }

  /** Brings each point that the sheets missed and that one tetrahedron joins to them onto them
    * (returns how many): a sheet triangle abc that is a
    * facet of a Delaunay tetrahedron abcv becomes the tent abv, bcv, cav over it, the smallest
    * such, with no edge across a gap. The tent keeps each edge on at most two triangles and each
    * fan one. */
  std::size_t detourThroughMissedPoints (const Tetrahedra& tetrahedra);

  /** Brings each point that the sheets still miss onto them by a cone (returns how many): where a
    * strip of one to three sheet triangles joined across edges, all of whose points are on its rim, has
    * each rim edge on a Delaunay triangle with the point, the strip becomes the cone from the
    * point over its rim, the smallest such, with no edge across a gap. A tent is the cone over one
    * triangle; a wider strip reaches a point under a sheet that the Delaunay triangles around it
    * do not share (the sheet took the other diagonal of a quadrilateral above it); a strip of none
    * is an edge on the sheets' boundary, and its cone one triangle more on it. */
  std::size_t coneOverMissedPoints (const Tetrahedra& tetrahedra);

  /** Brings each point that tents and cones did not reach onto the sheets whatever the Delaunay
    * faces around it (returns how many): the sheet triangle abc at one of its Delaunay neighbours
    * becomes abv, bcv, cav, or a boundary edge ab there gets the triangle from the point over it;
    * of those with no edge across a gap, the one with the fewest new triangles facing against the
    * triangle they replace or extend, then the smallest. The new triangles need not be Delaunay
    * faces and have no id (NO_ID); each is tied to its sheet as a hole's filling is. */
  std::size_t pinMissedPoints (const Tetrahedra& tetrahedra);

  /** Closes the holes of the sheets smaller than a gap the sampling resolves (where the growth
    * passed triangles by, or a long triangle was left out) by ear clipping, the shortest new edge
    * first; the filling's triangles need not be Delaunay and have no id (NO_ID). */
  void fillSmallHoles ();

  /** Per vertex, its triangles: those of vertex v are around[start[v] .. start[v + 1]). */
  std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>> trianglesAroundVertices () const;

  /** Per triangle, one triangle standing for its sheet (triangles joined across the edges they share, and the
    * filling of a hole to the hole's rim). */
  std::vector<std::uint32_t> sheets () const;

  /** Drops, at each point where the grown triangles make more than one fan, all but the largest. */
  void dropExtraFans ();

  /** Takes the crumbs (CRUMB_POINTS) off the sheets, their points as if never reached. */
  void liftCrumbs ();

  /** Puts back the crumbs' triangles whose points the tents did not bring onto a sheet: a crumb
    * that is a part of its own. */
  void restoreCrumbs ();

  /** Lets go of the candidates, their index and the queues: the growth is over. */
  void forgetCandidates ()
  {
    for (auto* v : {&candidates_, &edge_start_, &edge_candidates_, &placed_, &open_edges_})
      std::vector<std::uint32_t> ().swap (*v);
    std::vector<Candidate> ().swap (about_);
    std::vector<std::uint8_t> ().swap (edge_forward_);
    forgetQueues ();
  }

  /** Lets go of the queues' memory, which they keep when they empty. */
  void forgetQueues ()
  {
    std::vector<Entry> ().swap (notches_);
    queue_ = Queue ();
  }

  /** The grown triangles, each connected sheet turned so that the sum over its triangles of
    * \a facing (triangle) is not negative; where it is 0, the sum of \a tieBreak (triangles,
    * ids), one value per triangle. */
  template <typename Facing, typename TieBreak>
  Boundary orientedSheets (const Facing& facing, const TieBreak& tieBreak);

private:
  struct Entry
  {
    std::uint32_t candidate;
    SimplexId edge; // the front edge it is placed across
  };

  /** The queue of the candidates that fill no notch: those that bring a new point first, then the
    * smallest (by \a size, the squared longest edge) to within an eighth of an octave, the last
    * queued first among those; each step in constant time, where a heap of millions of entries
    * would miss the cache at every level. */
  class Queue
  {
  public:
    bool empty () const { return size_ == 0; }
    void push (bool brings_new, float size, const Entry& e)
    {
      std::uint32_t bits;
      std::memcpy (&bits, &size, sizeof bits); // a positive float's bits grow with it
      const std::size_t b = (brings_new ? 0 : OCTAVES) + (bits >> 20);
      buckets_[b].push_back (e);
      lowest_ = std::min (lowest_, b);
      ++size_;
    }
    Entry pop ()
    {
      while (buckets_[lowest_].empty ())
        ++lowest_;
      const Entry e = buckets_[lowest_].back ();
      buckets_[lowest_].pop_back ();
      --size_;
      return e;
    }

  private:
    static constexpr std::size_t OCTAVES = std::size_t (1) << 11; // exponent and 3 bits of mantissa
    std::vector<std::vector<Entry>> buckets_ = std::vector<std::vector<Entry>> (2 * OCTAVES);
    std::size_t lowest_ = 2 * OCTAVES, size_ = 0;
  };

  double distance (std::uint32_t a, std::uint32_t b) const { return detail::distance (positions_[a], positions_[b]); }

  /** The spacing at each point of W: the length of its third-shortest edge in W (its longest, with
    * fewer), or the median of its neighbours' where that is less, which the long edges of a rim
    * or a bridge do not inflate. */
  void measureSpacing (const Boundary& w)
  {
    const std::uint32_t nv = complex_.numVertices ();
    // W's edges, each once, in the order of their ids: marked on all threads, then listed.
    std::vector<std::atomic<std::uint8_t>> in_w (complex_.size (1));
    parallelForEach (w.triangle_ids.size (), [&] (std::size_t i) {
      for (SimplexId e : edgesOf (complex_, w.triangle_ids[i]))
        in_w[e].store (1, std::memory_order_relaxed);
    });
    std::vector<std::array<std::uint32_t, 2>> edges (w.dangling_edges.begin (), w.dangling_edges.end ());
    const std::size_t dangling = edges.size ();
    fillInOrder (
        in_w.size (), [&] (std::size_t e) { return std::size_t (in_w[e].load (std::memory_order_relaxed)); },
        [&] (std::size_t total) { edges.resize (dangling + total); },
        [&] (std::size_t e, std::size_t at) {
          if (in_w[e].load (std::memory_order_relaxed))
            edges[dangling + at++] = {complex_.vertex (1, e, 0), complex_.vertex (1, e, 1)};
          return at;
        });
    std::vector<std::atomic<std::uint8_t>> ().swap (in_w);
    std::vector<std::uint32_t> start (nv + 1, 0);
    for (const auto& [a, b] : edges)
    {
      ++start[a + 1];
      ++start[b + 1];
    }
    for (std::uint32_t v = 0; v < nv; ++v)
      start[v + 1] += start[v];
    std::vector<std::uint32_t> neighbours (start.back ());
    std::vector<std::uint32_t> at (start.begin (), start.end () - 1);
    for (const auto& [a, b] : edges)
    {
      neighbours[at[a]++] = b;
      neighbours[at[b]++] = a;
    }
    std::vector<std::array<std::uint32_t, 2>> ().swap (edges);
    std::vector<double> lengths (start.back ());
    parallelForEach (nv, [&] (std::size_t v) {
      for (std::uint32_t k = start[v]; k < start[v + 1]; ++k)
        lengths[k] = distance (static_cast<std::uint32_t> (v), neighbours[k]);
    });
    std::vector<double> third (nv, 0.0);
    parallelForEach (nv, [&] (std::size_t v) {
      if (start[v] == start[v + 1])
        return;
      const auto first = lengths.begin () + start[v], last = lengths.begin () + start[v + 1];
      const auto k = first + std::min<std::ptrdiff_t> (2, last - first - 1);
      std::nth_element (first, k, last);
      third[v] = *k;
    });
    // A point at a rim, with few edges in the sheet, takes its neighbours' spacing where that is less.
    spacing_.assign (nv, 0.0);
    parallelForEach (nv, [&] (std::size_t v) {
      if (start[v] == start[v + 1])
        return;
      thread_local std::vector<double> scratch;
      scratch.clear ();
      for (std::uint32_t k = start[v]; k < start[v + 1]; ++k)
        scratch.push_back (third[neighbours[k]]);
      const auto middle = scratch.begin () + std::ptrdiff_t (scratch.size ()) / 2;
      std::nth_element (scratch.begin (), middle, scratch.end ());
      spacing_[v] = std::min (third[v], *middle);
    });
  }

  /** Does an edge of the triangle \a v span a gap the sampling resolves: longer than
    * GAP_SPACINGS times the spacing at both of its ends? */
  bool spansGap (const std::uint32_t* v) const
  {
    return edgeSpansGap (v[0], v[1]) || edgeSpansGap (v[1], v[2]) || edgeSpansGap (v[2], v[0]);
  }
  bool edgeSpansGap (std::uint32_t a, std::uint32_t b) const
  {
    return distance (a, b) > GAP_SPACINGS * std::max (spacing_[a], spacing_[b]);
  }

  void addTrianglesAroundDanglingEdges (const Tetrahedra& tetrahedra, const Boundary& w)
  {
    if (w.dangling_edges.empty ())
      return;
    std::vector<std::uint8_t> listed (complex_.size (2), 0);
    for (SimplexId id : candidates_)
      listed[id] = 1;
    Star star;
    for (const auto& [u, v] : w.dangling_edges)
    {
      tetrahedra.gatherStar (u, star);
      for (std::uint32_t t : star.tetrahedra ())
        for (int i = 0; i < 4; ++i)
        {
          const Simplex f = complex_.facet (3, t, i);
          const std::uint32_t* fv = complex_.vertices (2, f.id);
          const bool has_u = fv[0] == u || fv[1] == u || fv[2] == u;
          const bool has_v = fv[0] == v || fv[1] == v || fv[2] == v;
          if (has_u && has_v && !listed[f.id] && !spansGap (fv))
          {
            listed[f.id] = 1;
            candidates_.push_back (f.id);
          }
        }
    }
  }

public:
  /** Per point, the direction across the layer: the eigenvector of the least eigenvalue of the
    * sum, over the point and its Delaunay neighbours, of each one's covariance with its own
    * neighbours (no edge across a gap): a structure tensor over about two rings, which noise
    * across the layer of a spacing does not turn over. */
  void measureLayerNormals ()
  {
    const std::uint32_t nv = complex_.numVertices ();
    std::vector<std::uint32_t> start (nv + 1, 0), around;
    const std::size_t ne = complex_.size (1);
    for (SimplexId e = 0; e < ne; ++e)
    {
      const std::uint32_t* v = complex_.vertices (1, e);
      if (!edgeSpansGap (v[0], v[1]))
      {
        ++start[v[0] + 1];
        ++start[v[1] + 1];
      }
    }
    for (std::uint32_t v = 0; v < nv; ++v)
      start[v + 1] += start[v];
    around.resize (start.back ());
    std::vector<std::uint32_t> at (start.begin (), start.end () - 1);
    for (SimplexId e = 0; e < ne; ++e)
    {
      const std::uint32_t* v = complex_.vertices (1, e);
      if (!edgeSpansGap (v[0], v[1]))
      {
        around[at[v[0]]++] = v[1];
        around[at[v[1]]++] = v[0];
      }
    }
    // Each point's covariance with its neighbours, from their offsets to it (far from the origin,
    // the positions' own squares would cancel): the upper triangle, xx xy xz yy yz zz.
    std::vector<std::array<double, 6>> covariance (nv);
    parallelForEach (nv, [&] (std::size_t v) {
      const Point3& o = positions_[v];
      double mean[3] = {0, 0, 0}, second[6] = {0, 0, 0, 0, 0, 0};
      for (std::uint32_t k = start[v]; k < start[v + 1]; ++k)
      {
        const Point3& p = positions_[around[k]];
        const double d[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
        for (int i = 0, at = 0; i < 3; ++i)
        {
          mean[i] += d[i];
          for (int j = i; j < 3; ++j)
            second[at++] += d[i] * d[j];
        }
      }
      const double n = double (start[v + 1] - start[v] + 1); // the point itself at offset 0
      for (int i = 0, at = 0; i < 3; ++i)
        for (int j = i; j < 3; ++j, ++at)
          covariance[v][at] = second[at] / n - mean[i] * mean[j] / (n * n);
    });
    layer_normal_.assign (nv, {0.0f, 0.0f, 0.0f});
    parallelForEach (nv, [&] (std::size_t v) {
      if (start[v + 1] - start[v] < 2)
        return;
      std::array<double, 6> sum = covariance[v];
      for (std::uint32_t k = start[v]; k < start[v + 1]; ++k)
        for (int i = 0; i < 6; ++i)
          sum[i] += covariance[around[k]][i];
      Eigen::Matrix3d tensor;
      tensor << sum[0], sum[1], sum[2], sum[1], sum[3], sum[4], sum[2], sum[4], sum[5];
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
      solver.computeDirect (tensor);
      const Eigen::Vector3d n = solver.eigenvectors ().col (0);
      layer_normal_[v] = {float (n[0]), float (n[1]), float (n[2])};
    });
    facing_.assign (nv, 0);
  }

private:
  /** \a n (a triangle's normal) along point \a v's direction across the layer: its sign says
    * which side of the layer the triangle faces there; 0 where \a v has no direction. */
  double alongLayerNormal (const std::array<double, 3>& n, std::uint32_t v) const
  {
    const auto& l = layer_normal_[v];
    return n[0] * l[0] + n[1] * l[1] + n[2] * l[2];
  }

  /** Does triangle \a t, as oriented, face the way the sheet faces at each of its points, point
    * \a apex the way \a apex_facing says if that is not 0? */
  bool facesAlong (const Triangle& t, std::uint32_t apex, std::int8_t apex_facing) const
  {
    const std::array<double, 3> n = areaNormal (t, positions_);
    for (std::uint32_t v : t)
    {
      const std::int8_t f = v == apex && apex_facing != 0 ? apex_facing : facing_[v];
      const auto& l = layer_normal_[v];
      if (l[0] == 0 && l[1] == 0 && l[2] == 0)
        continue; // too few neighbours to tell (a point on no edge of W has none): no way to keep
      if (f * alongLayerNormal (n, v) <= 0)
        return false;
    }
    return true;
  }

  /** Queues the candidates on front edge \a e that are not placed. */
  void queueAround (SimplexId e)
  {
    for (std::uint32_t k = edge_start_[e]; k < edge_start_[e + 1]; ++k)
    {
      const std::uint32_t c = edge_candidates_[k];
      if (placed_[c] != NONE)
        continue;
      int on_front = 0;
      for (SimplexId f : about_[c].e)
        on_front += edge_count_[f] == 1;
      const std::uint32_t* v = about_[c].v.data ();
      const bool brings_new = !on_[v[0]] || !on_[v[1]] || !on_[v[2]];
      if (on_front >= 2)
        notches_.push_back ({c, e}); // placed at once, in any order: each closes a notch
      else
        queue_.push (brings_new, about_[c].size, {c, e});
    }
  }

  /** The edge of the complex between \a a and \a b, one of \a c's. */
  SimplexId edgeBetween (std::uint32_t c, std::uint32_t a, std::uint32_t b) const
  {
    const std::uint32_t* v = about_[c].v.data ();
    const std::array<SimplexId, 3>& e = about_[c].e;
    for (int k = 0; k < 3; ++k)
      if ((v[k] == a && v[(k + 1) % 3] == b) || (v[k] == b && v[(k + 1) % 3] == a))
        return e[k];
    return e[0]; // not reached: a and b are two of c's vertices
  }

  /** Does the one grown triangle on edge \a e traverse it from \a a to \a b? */
  bool traverses (SimplexId e, std::uint32_t a, std::uint32_t b) const { return (a < b) == (edge_forward_[e] != 0); }

  void place (std::uint32_t c, const Triangle& t)
  {
    if (!facing_.empty ())
    {
      const std::array<double, 3> n = areaNormal (t, positions_);
      for (std::uint32_t v : t)
        if (facing_[v] == 0)
          facing_[v] = alongLayerNormal (n, v) < 0 ? -1 : 1;
    }
    placed_[c] = static_cast<std::uint32_t> (triangles_.size ());
    triangles_.push_back (t);
    ids_.push_back (candidates_[c]);
    for (int k = 0; k < 3; ++k)
    {
      const std::uint32_t a = t[k], b = t[(k + 1) % 3];
      const SimplexId e = edgeBetween (c, a, b);
      if (edge_count_[e]++ == 0)
      {
        edge_forward_[e] = a < b;
        ++open_edges_[a];
        ++open_edges_[b];
      }
      else
      {
        --open_edges_[a];
        --open_edges_[b];
      }
      on_[a] = 1;
    }
    for (int k = 0; k < 3; ++k)
    {
      const SimplexId e = edgeBetween (c, t[k], t[(k + 1) % 3]);
      if (edge_count_[e] == 1)
        queueAround (e);
    }
  }

  void tryPlace (std::uint32_t c, SimplexId e)
  {
    if (edge_count_[e] != 1)
      return;
    const std::uint32_t* v = about_[c].v.data ();
    const std::uint32_t* ev = complex_.vertices (1, e);
    std::uint32_t apex = v[0];
    for (int k = 0; k < 3; ++k)
      if (v[k] != ev[0] && v[k] != ev[1])
        apex = v[k];
    // Across the front edge from a to b (as the grown triangle there goes), the new triangle goes
    // from b to a: consistently oriented.
    const std::uint32_t a = traverses (e, ev[0], ev[1]) ? ev[0] : ev[1], b = a == ev[0] ? ev[1] : ev[0];
    const Triangle t{b, a, apex};
    const SimplexId ac = edgeBetween (c, a, apex), cb = edgeBetween (c, apex, b);
    if (edge_count_[ac] >= 2 || edge_count_[cb] >= 2)
      return;
    if ((edge_count_[ac] == 1 && !traverses (ac, apex, a)) || (edge_count_[cb] == 1 && !traverses (cb, b, apex)))
      return;
    std::int8_t apex_facing = 0; // the way a new point faces: as the front's points do
    if (!facing_.empty ())
    {
      if (facing_[apex] == 0)
      {
        const auto &l = layer_normal_[apex], &la = layer_normal_[a], &lb = layer_normal_[b];
        double along = 0;
        for (int k = 0; k < 3; ++k)
          along += l[k] * (facing_[a] * la[k] + facing_[b] * lb[k]);
        apex_facing = along < 0 ? -1 : 1;
      }
      if (!facesAlong (t, apex, apex_facing))
        return; // it would turn the sheet over
    }
    if (on_[apex])
    {
      if (c >= extra_from_ && c < crack_from_)
        return; // a triangle around a dangling edge only brings its point on
      if (edge_count_[ac] == 0 && edge_count_[cb] == 0)
      {
        if (open_edges_[apex] == 0)
          return; // its fans are closed: a second would never join them
        touched_.push_back (apex);
      }
    }
    if (apex_facing != 0)
      facing_[apex] = apex_facing;
    place (c, t);
  }

  const SimplicialComplex& complex_;
  const std::vector<Point3>& positions_;
  std::vector<double> spacing_;       // per vertex: see measureSpacing() (0: on no edge of W)
  std::vector<SimplexId> candidates_; // triangle ids: W's, then those around its dangling edges
  struct Candidate
  {
    std::array<std::uint32_t, 3> v; // its vertices and edges as in the complex, read at every step
    std::array<SimplexId, 3> e;     // of the growth: kept together, one cache line
    float size;                     // squared longest edge
  };
  std::vector<Candidate> about_;    // per candidate
  std::uint32_t extra_from_ = 0;    // candidates from here on lie around a dangling edge of W,
  std::uint32_t crack_from_ = NONE; // and from here on across a crack (closeCracks())
  std::vector<std::uint32_t> edge_start_, edge_candidates_;
  std::vector<std::uint8_t> edge_count_, edge_forward_; // per edge: grown triangles on it; the one's direction
  std::vector<std::uint8_t> on_;                        // per vertex: on a grown triangle
  std::vector<std::array<float, 3>> layer_normal_;      // per vertex, if the layer is noisy: see measureLayerNormals()
  std::vector<std::int8_t> facing_;       // per vertex: the sheet there faces +-layer_normal_ (0: not yet)
  std::vector<std::uint32_t> open_edges_; // per vertex: its grown edges on one triangle
  std::vector<std::uint32_t> placed_;     // per candidate: its place in triangles_, or NONE
  std::vector<Triangle> triangles_;       // grown, oriented
  std::vector<SimplexId> ids_;
  std::vector<std::uint32_t> touched_; // points a triangle touched where its front met itself
  std::vector<Triangle> crumbs_;       // lifted by liftCrumbs(), with their ids
  std::vector<SimplexId> crumb_ids_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fill_partner_; // (filling triangle, one on its hole)
  std::vector<Entry> notches_;                                        // candidates with two edges on the front
  Queue queue_;                                                       // the others
};

std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>>
SheetGrowth::trianglesAroundVertices () const
{
  const std::uint32_t nv = complex_.numVertices ();
  std::vector<std::uint32_t> start (nv + 1, 0), around (3 * triangles_.size ());
  for (const Triangle& t : triangles_)
    for (std::uint32_t v : t)
      ++start[v + 1];
  for (std::uint32_t v = 0; v < nv; ++v)
    start[v + 1] += start[v];
  std::vector<std::uint32_t> at (start.begin (), start.end () - 1);
  for (std::uint32_t i = 0; i < triangles_.size (); ++i)
    for (std::uint32_t v : triangles_[i])
      around[at[v]++] = i;
  return {std::move (start), std::move (around)};
}

std::vector<std::uint32_t>
SheetGrowth::sheets () const
{
  UnionFind pieces (triangles_.size ());
  std::vector<std::uint32_t> first_on_edge (complex_.size (1), NONE);
  for (std::uint32_t i = 0; i < triangles_.size (); ++i)
    for (int k = 0; k < 3 && ids_[i] != NO_ID; ++k)
    {
      const SimplexId e = edgesOf (complex_, ids_[i])[k];
      if (first_on_edge[e] == NONE)
        first_on_edge[e] = i;
      else
        pieces.attach (i, first_on_edge[e]);
    }
  for (const auto& [filling, partner] : fill_partner_)
    pieces.attach (filling, partner);
  std::vector<std::uint32_t> sheet (triangles_.size ());
  for (std::uint32_t i = 0; i < sheet.size (); ++i)
    sheet[i] = pieces.find (i);
  return sheet;
}

void
SheetGrowth::liftCrumbs ()
{
  // Pieces by the points they share (a crumb shares none with the sheet it lies beside).
  const std::uint32_t nv = complex_.numVertices ();
  UnionFind pieces (nv);
  for (const Triangle& t : triangles_)
    for (int k = 1; k < 3; ++k)
      pieces.attach (t[k], t[0]);
  std::vector<std::uint32_t> points (nv, 0);
  for (std::uint32_t v = 0; v < nv; ++v)
    points[pieces.find (v)] += on_[v];
  const std::uint32_t largest = *std::max_element (points.begin (), points.end ());
  const auto crumb = [&] (std::uint32_t v) {
    const std::uint32_t n = points[pieces.find (v)];
    return n < CRUMB_POINTS && std::size_t (n) * CRUMB_OF <= largest;
  };
  std::size_t kept = 0;
  for (std::size_t i = 0; i < triangles_.size (); ++i)
    if (crumb (triangles_[i][0]))
    {
      crumbs_.push_back (triangles_[i]);
      crumb_ids_.push_back (ids_[i]);
    }
    else
    {
      triangles_[kept] = triangles_[i];
      ids_[kept++] = ids_[i];
    }
  triangles_.resize (kept);
  ids_.resize (kept);
  for (const Triangle& t : crumbs_)
    for (std::uint32_t v : t)
      on_[v] = 0;
}

void
SheetGrowth::restoreCrumbs ()
{
  std::vector<std::uint8_t> apart (crumbs_.size ()); // decided before any is put back
  for (std::size_t i = 0; i < crumbs_.size (); ++i)
    apart[i] = !on_[crumbs_[i][0]] && !on_[crumbs_[i][1]] && !on_[crumbs_[i][2]];
  for (std::size_t i = 0; i < crumbs_.size (); ++i)
    if (apart[i])
    {
      triangles_.push_back (crumbs_[i]);
      ids_.push_back (crumb_ids_[i]);
      for (std::uint32_t v : crumbs_[i])
        on_[v] = 1;
    }
  crumbs_.clear ();
  crumb_ids_.clear ();
}

void
SheetGrowth::dropExtraFans ()
{
  if (touched_.empty ())
    return;
  const std::uint32_t nv = complex_.numVertices ();
  std::vector<std::uint8_t> dropped (triangles_.size (), 0);
  // Named, not bound: a lambda below captures them (C++17).
  const auto by_vertex = trianglesAroundVertices ();
  const std::vector<std::uint32_t>&start = by_vertex.first, &around = by_vertex.second;
  std::vector<std::uint32_t> work = std::move (touched_), fan, members;
  std::sort (work.begin (), work.end ());
  work.erase (std::unique (work.begin (), work.end ()), work.end ());
  while (!work.empty ())
  {
    const std::uint32_t v = work.back ();
    work.pop_back ();
    // The fans at v: its triangles joined across the edges at v, by labels spread to a fixpoint.
    members.clear ();
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k)
      if (!dropped[around[k]])
        members.push_back (around[k]);
    fan.assign (members.size (), NONE);
    std::uint32_t fans = 0;
    const auto shares_edge_at_v = [&] (const Triangle& p, const Triangle& q) {
      for (std::uint32_t a : p)
        if (a != v && (q[0] == a || q[1] == a || q[2] == a))
          return true;
      return false;
    };
    for (std::size_t i = 0; i < members.size (); ++i)
    {
      if (fan[i] != NONE)
        continue;
      fan[i] = fans;
      std::vector<std::size_t> stack{i};
      while (!stack.empty ())
      {
        const std::size_t p = stack.back ();
        stack.pop_back ();
        for (std::size_t q = 0; q < members.size (); ++q)
          if (fan[q] == NONE && shares_edge_at_v (triangles_[members[p]], triangles_[members[q]]))
          {
            fan[q] = fans;
            stack.push_back (q);
          }
      }
      ++fans;
    }
    if (fans < 2)
      continue;
    std::vector<std::uint32_t> size (fans, 0);
    for (std::uint32_t f : fan)
      ++size[f];
    const auto largest = static_cast<std::uint32_t> (std::max_element (size.begin (), size.end ()) - size.begin ());
    for (std::size_t i = 0; i < members.size (); ++i)
      if (fan[i] != largest)
      {
        dropped[members[i]] = 1;
        for (std::uint32_t u : triangles_[members[i]])
          if (u != v)
            work.push_back (u); // its fans may have come apart
      }
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < triangles_.size (); ++i)
    if (!dropped[i])
    {
      triangles_[kept] = triangles_[i];
      ids_[kept++] = ids_[i];
    }
  triangles_.resize (kept);
  ids_.resize (kept);
  // A point whose every triangle was in a dropped fan is on no sheet now.
  std::fill (on_.begin (), on_.end (), 0);
  for (const Triangle& t : triangles_)
    for (std::uint32_t v : t)
      on_[v] = 1;
}

std::size_t
SheetGrowth::detourThroughMissedPoints (const Tetrahedra& tetrahedra)
{
  std::size_t brought = 0;
  std::vector<std::uint32_t> sheet_index (complex_.size (2), NONE);
  for (std::uint32_t i = 0; i < ids_.size (); ++i)
    sheet_index[ids_[i]] = i;
  Star star;
  for (std::uint32_t v = 0; v < complex_.numVertices (); ++v)
  {
    if (on_[v] || tetrahedra.tetrahedronOf (v) == NO_TETRAHEDRON)
      continue;
    tetrahedra.gatherStar (v, star);
    std::uint32_t best = NONE, best_tetrahedron = 0;
    double best_size = 0;
    for (std::uint32_t t : star.tetrahedra ())
    {
      const int apex = tetrahedra.localIndex (t, v);
      const std::uint32_t i = sheet_index[complex_.facet (3, t, apex).id];
      if (i == NONE)
        continue;
      const Triangle& abc = triangles_[i];
      double size = 0;
      bool gap = false;
      for (std::uint32_t a : abc)
      {
        gap = gap || edgeSpansGap (a, v);
        size = std::max (size, distance (a, v));
      }
      if (!gap && (best == NONE || size < best_size))
      {
        best = i;
        best_tetrahedron = t;
        best_size = size;
      }
    }
    if (best == NONE)
      continue;
    const Triangle abc = triangles_[best];
    const auto facetWithout = [&] (std::uint32_t u) {
      return complex_.facet (3, best_tetrahedron, tetrahedra.localIndex (best_tetrahedron, u)).id;
    };
    sheet_index[ids_[best]] = NONE;
    for (int k = 0; k < 3; ++k)
    {
      const Triangle tent{abc[k], abc[(k + 1) % 3], v};
      const SimplexId id = facetWithout (abc[(k + 2) % 3]);
      const std::uint32_t at = k == 0 ? best : static_cast<std::uint32_t> (triangles_.size ());
      if (k == 0)
      {
        triangles_[at] = tent;
        ids_[at] = id;
      }
      else
      {
        triangles_.push_back (tent);
        ids_.push_back (id);
      }
      sheet_index[id] = at;
    }
    on_[v] = 1;
    ++brought;
  }
  return brought;
}

std::size_t
SheetGrowth::coneOverMissedPoints (const Tetrahedra& tetrahedra)
{
  // Named, not bound: a lambda below captures them (C++17).
  const auto by_vertex = trianglesAroundVertices ();
  const std::vector<std::uint32_t>&start = by_vertex.first, &around = by_vertex.second;
  // Triangles replaced or given a neighbour in this round: the index no longer tells their edges.
  std::vector<std::uint8_t> touched (triangles_.size (), 0);
  // Nor does it tell the rims of this round's cones: a cone's triangle on a rim edge may be one the
  // index does not hold, and the edge already on two triangles.
  std::set<std::pair<std::uint32_t, std::uint32_t>> rims;
  std::size_t brought = 0;
  Star star;
  std::vector<LinkEdge> link;
  const auto linkTriangle = [&] (std::uint32_t a, std::uint32_t b) {
    const std::pair key (std::min (a, b), std::max (a, b));
    const auto it = std::lower_bound (link.begin (), link.end (), std::pair (key, SimplexId (0)));
    return it != link.end () && it->first == key ? it->second : NO_ID;
  };
  std::vector<std::uint32_t> near, strip, best, corners, on_edge;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> rim, best_rim, edges;
  double best_size = 0;
  // Takes the cone over \a rim (the strip's boundary, each edge as its triangle runs along it) if
  // it is the smallest so far.
  const auto consider = [&] (std::uint32_t v) {
    double size = 0;
    for (const auto& [a, b] : rim)
    {
      if (linkTriangle (a, b) == NO_ID || edgeSpansGap (a, v) || edgeSpansGap (b, v))
        return;
      size = std::max ({size, distance (a, v), distance (b, v)});
    }
    if (best_rim.empty () || size < best_size)
    {
      best = strip;
      best_rim = rim;
      best_size = size;
    }
  };
  for (std::uint32_t v = 0; v < complex_.numVertices (); ++v)
  {
    if (on_[v] || tetrahedra.tetrahedronOf (v) == NO_TETRAHEDRON)
      continue;
    gatherLinkEdges (tetrahedra, v, star, link);
    // The sheet triangles with an edge on the link (each triangle of a strip has one), and the
    // link edges on one sheet triangle only (a sheet's boundary), each a strip of none.
    best.clear ();
    best_rim.clear ();
    near.clear ();
    for (const auto& [ab, id] : link)
    {
      if (rims.count (ab))
        continue;
      on_edge.clear ();
      bool known = true;
      for (std::uint32_t k = start[ab.first]; k < start[ab.first + 1]; ++k)
      {
        const std::uint32_t i = around[k];
        const Triangle& t = triangles_[i];
        if (t[0] == ab.second || t[1] == ab.second || t[2] == ab.second)
        {
          on_edge.push_back (i);
          known = known && !touched[i] && ids_[i] != NO_ID;
        }
      }
      if (!known)
        continue;
      near.insert (near.end (), on_edge.begin (), on_edge.end ());
      if (on_edge.size () == 1)
      {
        const Triangle& t = triangles_[on_edge[0]];
        const bool forward = runsFrom (t, ab.first, ab.second);
        strip.clear ();
        rim.assign (1, forward ? std::pair (ab.second, ab.first) : ab);
        consider (v);
      }
    }
    std::sort (near.begin (), near.end ());
    near.erase (std::unique (near.begin (), near.end ()), near.end ());
    // Strips of one, two and three triangles joined across edges.
    const auto tryStrip = [&] () {
      edges.clear ();
      corners.clear ();
      for (std::uint32_t i : strip)
        for (int k = 0; k < 3; ++k)
        {
          const Triangle& t = triangles_[i];
          edges.push_back ({t[k], t[(k + 1) % 3]});
          corners.push_back (t[k]);
        }
      std::sort (corners.begin (), corners.end ());
      corners.erase (std::unique (corners.begin (), corners.end ()), corners.end ());
      if (corners.size () != strip.size () + 2)
        return; // a point inside the strip
      rim.clear ();
      for (const auto& [a, b] : edges)
        if (std::find (edges.begin (), edges.end (), std::pair (b, a)) == edges.end ())
          rim.push_back ({a, b});
      if (rim.size () == corners.size ())
        consider (v);
    };
    const auto adjacent = [&] (std::uint32_t i, std::uint32_t j) {
      int shared = 0;
      for (std::uint32_t a : triangles_[i])
        for (std::uint32_t b : triangles_[j])
          shared += a == b;
      return shared == 2;
    };
    for (std::size_t x = 0; x < near.size (); ++x)
    {
      strip.assign (1, near[x]);
      tryStrip ();
      for (std::size_t y = 0; y < near.size (); ++y)
      {
        if (y == x || !adjacent (near[x], near[y]))
          continue;
        if (y > x)
        {
          strip = {near[x], near[y]};
          tryStrip ();
        }
        for (std::size_t z = x + 1; z < near.size (); ++z)
          if (z != y && adjacent (near[y], near[z]))
          {
            strip = {near[x], near[y], near[z]}; // a path x - y - z, each once (x < z)
            tryStrip ();
          }
      }
    }
    if (best_rim.empty ())
      continue;
    for (std::size_t k = 0; k < best_rim.size (); ++k)
    {
      const auto [a, b] = best_rim[k];
      const Triangle cone{a, b, v};
      const SimplexId id = linkTriangle (a, b);
      rims.insert ({std::min (a, b), std::max (a, b)});
      if (k < best.size ())
      {
        triangles_[best[k]] = cone;
        ids_[best[k]] = id;
        touched[best[k]] = 1;
      }
      else
      {
        triangles_.push_back (cone);
        ids_.push_back (id);
      }
    }
    if (best.empty ())
      for (std::uint32_t k = start[best_rim[0].first]; k < start[best_rim[0].first + 1]; ++k)
        touched[around[k]] = 1; // the flap's neighbour among them
    on_[v] = 1;
    ++brought;
  }
  return brought;
}

std::size_t
SheetGrowth::pinMissedPoints (const Tetrahedra& tetrahedra)
{
  // Named, not bound: a lambda below captures them (C++17).
  const auto by_vertex = trianglesAroundVertices ();
  const std::vector<std::uint32_t>&start = by_vertex.first, &around = by_vertex.second;
  // Triangles replaced or given a neighbour in this round: the index no longer tells their edges.
  std::vector<std::uint8_t> touched (triangles_.size (), 0);
  // The triangle other than \a i on edge ab, or NONE: on a manifold sheet there is at most one.
  const auto across = [&] (std::uint32_t i, std::uint32_t a, std::uint32_t b) {
    for (std::uint32_t k = start[a]; k < start[a + 1]; ++k)
    {
      const Triangle& t = triangles_[around[k]];
      if (around[k] != i && (t[0] == b || t[1] == b || t[2] == b))
        return around[k];
    }
    return NONE;
  };
  std::size_t brought = 0;
  Star star;
  std::vector<std::uint32_t> near;
  for (std::uint32_t v = 0; v < complex_.numVertices (); ++v)
  {
    if (on_[v] || tetrahedra.tetrahedronOf (v) == NO_TETRAHEDRON)
      continue;
    tetrahedra.gatherStar (v, star);
    near.clear ();
    for (std::uint32_t t : star.tetrahedra ())
      for (int k = 0; k < 4; ++k)
        if (const std::uint32_t u = tetrahedra.vertex (t, k); on_[u])
          near.insert (near.end (), around.begin () + start[u], around.begin () + start[u + 1]);
    std::sort (near.begin (), near.end ());
    near.erase (std::unique (near.begin (), near.end ()), near.end ());
    // The best so far: triangle i, and its edge k (a flap over it) or k = 3 (a tent over it); the
    // fewest new triangles folded over against it, then the smallest.
    std::uint32_t best = NONE;
    int best_edge = 0, best_folds = 0;
    double best_size = 0;
    for (std::uint32_t i : near)
    {
      const Triangle& t = triangles_[i];
      if (touched[i] || edgeSpansGap (t[0], v) || edgeSpansGap (t[1], v) || edgeSpansGap (t[2], v))
        continue;
      const double d[3] = {distance (t[0], v), distance (t[1], v), distance (t[2], v)};
      const std::array<double, 3> n = areaNormal (t, positions_);
      const auto folded = [&] (const Triangle& f) {
        const std::array<double, 3> m = areaNormal (f, positions_);
        return n[0] * m[0] + n[1] * m[1] + n[2] * m[2] <= 0 ? 1 : 0;
      };
      for (int k = 0; k < 4; ++k)
      {
        if (k < 3 && across (i, t[k], t[(k + 1) % 3]) != NONE)
          continue; // no boundary edge
        const double size = k < 3 ? std::max (d[k], d[(k + 1) % 3]) : std::max ({d[0], d[1], d[2]});
        const int folds = k < 3 ? folded ({t[(k + 1) % 3], t[k], v})
                                : folded ({t[0], t[1], v}) + folded ({t[1], t[2], v}) + folded ({t[2], t[0], v});
        if (best == NONE || std::pair (folds, size) < std::pair (best_folds, best_size))
        {
          best = i;
          best_edge = k;
          best_folds = folds;
          best_size = size;
        }
      }
    }
    if (best == NONE)
      continue;
    const Triangle abc = triangles_[best];
    touched[best] = 1;
    const auto add = [&] (const Triangle& t, std::uint32_t partner) {
      fill_partner_.push_back ({static_cast<std::uint32_t> (triangles_.size ()), partner});
      triangles_.push_back (t);
      ids_.push_back (NO_ID);
    };
    if (best_edge < 3)
      add ({abc[(best_edge + 1) % 3], abc[best_edge], v}, best);
    else
    {
      // Tied to the sheet across each rim edge; their ids are gone, so edges no longer tie them.
      std::array<std::uint32_t, 3> rim;
      for (int k = 0; k < 3; ++k)
        if ((rim[k] = across (best, abc[k], abc[(k + 1) % 3])) != NONE)
        {
          fill_partner_.push_back ({best, rim[k]});
          touched[rim[k]] = 1; // its edge with abc is on a triangle the index does not hold
        }
      triangles_[best] = {abc[0], abc[1], v};
      ids_[best] = NO_ID;
      for (int k = 1; k < 3; ++k)
      {
        add ({abc[k], abc[(k + 1) % 3], v}, rim[k] == NONE ? best : rim[k]);
        fill_partner_.push_back ({static_cast<std::uint32_t> (triangles_.size () - 1), best});
      }
    }
    on_[v] = 1;
    ++brought;
  }
  return brought;
}

void
SheetGrowth::fillSmallHoles ()
{
  // The sheets' triangles per edge and per vertex; every triangle so far is a Delaunay face.
  const std::uint32_t nv = complex_.numVertices ();
  std::fill (edge_count_.begin (), edge_count_.end (), 0);
  for (SimplexId id : ids_)
    for (SimplexId e : edgesOf (complex_, id))
      ++edge_count_[e];
  // Named, not bound: a lambda below captures them (C++17).
  const auto by_vertex = trianglesAroundVertices ();
  const std::vector<std::uint32_t>&start = by_vertex.first, &around = by_vertex.second;
  // The boundary as a successor per vertex: out[a] = b for an edge a -> b of one triangle only;
  // each vertex of a manifold sheet has at most one, so the loops are simple.
  std::vector<std::uint32_t> out (nv, NONE), triangle_of (nv, NONE);
  for (std::uint32_t i = 0; i < triangles_.size (); ++i)
  {
    const Triangle& t = triangles_[i];
    const std::uint32_t* v = complex_.vertices (2, ids_[i]);
    const std::array<SimplexId, 3> e = edgesOf (complex_, ids_[i]);
    for (int k = 0; k < 3; ++k)
      if (edge_count_[e[k]] == 1)
      {
        // Edge k of the complex's triangle joins its vertices k and k + 1; the sheet's triangle
        // goes from a to b along it.
        const std::uint32_t a = v[k], b = v[(k + 1) % 3];
        const bool forward = runsFrom (t, a, b);
        out[forward ? a : b] = forward ? b : a;
        triangle_of[forward ? a : b] = i;
      }
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> diagonals; // added to this hole, as (lower, higher)
  const auto joined = [&] (std::uint32_t p, std::uint32_t r) {
    for (std::uint32_t k = start[p]; k < start[p + 1]; ++k)
    {
      const Triangle& t = triangles_[around[k]];
      if (t[0] == r || t[1] == r || t[2] == r)
        return true;
    }
    return std::find (diagonals.begin (), diagonals.end (), std::pair (std::min (p, r), std::max (p, r))) !=
           diagonals.end ();
  };
  // The sheets, by union-find over the edges they share: a sheet's outer boundary, its longest
  // loop, is no hole.
  const std::vector<std::uint32_t> sheet = sheets ();
  const auto find = [&] (std::uint32_t i) { return sheet[i]; };
  struct Loop
  {
    std::uint32_t first, edges;
    double perimeter, widest;
  };
  std::vector<Loop> loops;
  std::vector<double> outer (triangles_.size (), 0.0); // per sheet: its longest loop's perimeter
  {
    std::vector<std::uint8_t> visited (nv, 0);
    for (std::uint32_t first = 0; first < nv; ++first)
    {
      if (out[first] == NONE || visited[first])
        continue;
      Loop l{first, 0, 0.0, 0.0};
      std::uint32_t v = first;
      while (v != NONE && !visited[v])
      {
        visited[v] = 1;
        ++l.edges;
        l.widest = std::max (l.widest, spacing_[v]);
        if (out[v] != NONE)
          l.perimeter += distance (v, out[v]);
        v = out[v];
      }
      if (v != first)
        continue; // not a closed loop (where the sheets touch themselves at a point)
      double& longest = outer[find (triangle_of[first])];
      longest = std::max (longest, l.perimeter);
      loops.push_back (l);
    }
  }
  std::vector<std::uint32_t> loop, polygon;
  std::vector<Triangle> ears;
  // Holes do not share a vertex (each has one successor): a diagonal matters within its hole only.
  for (const Loop& l : loops)
  {
    // No longer round than a hole as wide as a gap the sampling resolves, at the loop's widest
    // spacing; not the outer boundary.
    if (l.edges < 3 || l.edges > MAX_HOLE_EDGES || l.perimeter > M_PI * GAP_SPACINGS * l.widest ||
        l.perimeter >= outer[find (triangle_of[l.first])])
      continue;
    loop.clear ();
    for (std::uint32_t v = l.first; loop.empty () || v != l.first; v = out[v])
      loop.push_back (v);
    // Ear clipping, the ear with the shortest new edge first; the loop's edges are traversed the
    // other way round by the filling, so it runs through the loop backwards.
    polygon.assign (loop.rbegin (), loop.rend ());
    ears.clear ();
    diagonals.clear ();
    while (polygon.size () > 3)
    {
      const std::size_t n = polygon.size ();
      std::size_t best = n;
      double shortest = 0;
      for (std::size_t i = 0; i < n; ++i)
      {
        const std::uint32_t p = polygon[(i + n - 1) % n], r = polygon[(i + 1) % n];
        if (!joined (p, r) && (best == n || distance (p, r) < shortest)) // else three triangles on p r
        {
          best = i;
          shortest = distance (p, r);
        }
      }
      if (best == n)
        break;
      const std::uint32_t p = polygon[(best + n - 1) % n], q = polygon[best], r = polygon[(best + 1) % n];
      ears.push_back ({p, q, r});
      diagonals.push_back ({std::min (p, r), std::max (p, r)});
      polygon.erase (polygon.begin () + std::ptrdiff_t (best));
    }
    if (polygon.size () > 3)
      continue; // the diagonals it needs are edges already: left open
    ears.push_back ({polygon[0], polygon[1], polygon[2]});
    for (const Triangle& t : ears)
    {
      fill_partner_.push_back ({static_cast<std::uint32_t> (triangles_.size ()), triangle_of[loop[0]]});
      triangles_.push_back (t);
      ids_.push_back (NO_ID);
    }
  }
}

template <typename Facing, typename TieBreak>
Boundary
SheetGrowth::orientedSheets (const Facing& facing, const TieBreak& tieBreak)
{
  const std::size_t n = triangles_.size ();
  const std::vector<std::uint32_t> sheet = sheets ();
  const auto find = [&] (std::uint32_t i) { return sheet[i]; };
  std::vector<double> vote (n, 0.0);
  for (std::uint32_t i = 0; i < n; ++i)
    vote[find (i)] += facing (triangles_[i]);
  // Only a sheet with no up or down needs the tie broken, by what it asks the solid.
  bool tied = false;
  for (std::uint32_t i = 0; i < n && !tied; ++i)
    tied = find (i) == i && vote[i] == 0;
  if (tied)
  {
    const std::vector<double> second = tieBreak (triangles_, ids_);
    std::vector<double> sum (n, 0.0);
    for (std::uint32_t i = 0; i < n; ++i)
      sum[find (i)] += second[i];
    for (std::uint32_t i = 0; i < n; ++i)
      if (find (i) == i && vote[i] == 0)
        vote[i] = sum[i];
  }
  Boundary out;
  out.triangles = std::move (triangles_);
  out.triangle_ids = std::move (ids_);
  for (std::uint32_t i = 0; i < n; ++i)
    if (vote[find (i)] < 0)
      std::swap (out.triangles[i][1], out.triangles[i][2]);
  return out;
}

} // namespace

Boundary
openSheet (const Tetrahedra& tetrahedra, Boundary w, const std::vector<Point3>& positions,
           const std::function<std::vector<std::uint8_t> ()>& inside, const std::optional<Point3>& viewpoint,
           bool noisy)
{
  const SimplicialComplex& complex = tetrahedra.complex ();
  SheetGrowth growth (tetrahedra, w, positions);
  w = {}; // the candidates have what the growth needs of it
  if (noisy)
    growth.measureLayerNormals ();
  growth.grow ();
  growth.closeCracks (tetrahedra);
  growth.forgetCandidates ();
  growth.dropExtraFans ();
  growth.liftCrumbs ();
  // Points buried in X (a wall between a roof and the ground X fills) and the crumbs' come on a
  // tent at a time; the few that no tent reaches, by cones.
  for (int round = 0; round < MAX_TENT_ROUNDS && growth.detourThroughMissedPoints (tetrahedra) > 0; ++round)
  {}
  for (int round = 0; round < MAX_TENT_ROUNDS && growth.coneOverMissedPoints (tetrahedra) > 0; ++round)
  {}
  growth.restoreCrumbs ();
  growth.fillSmallHoles ();
  while (growth.pinMissedPoints (tetrahedra) > 0)
  {}
  // A sheet with no up or down faces out of the labelled solid: per triangle on its surface, +-area.
  const auto out_of_solid = [&] (const std::vector<Triangle>& triangles, const std::vector<SimplexId>& ids) {
    const Boundary solid = extractSolidBoundary (tetrahedra, inside ());
    // Per triangle of the complex on the solid's surface: 1 as it goes there in ascending vertex
    // order up to an even permutation, 2 odd.
    std::vector<std::uint8_t> solid_order (complex.size (2), 0);
    for (std::size_t i = 0; i < solid.triangles.size (); ++i)
      solid_order[solid.triangle_ids[i]] = evenOrder (solid.triangles[i]) ? 1 : 2;
    std::vector<double> vote (triangles.size (), 0.0);
    for (std::size_t i = 0; i < triangles.size (); ++i)
    {
      const std::uint8_t order = ids[i] == NO_ID ? 0 : solid_order[ids[i]];
      const std::array<double, 3> n = areaNormal (triangles[i], positions);
      const double area = std::sqrt (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      vote[i] = order == 0 ? 0.0 : (order == 1) == evenOrder (triangles[i]) ? area : -area;
    }
    return vote;
  };
  if (viewpoint)
    return growth.orientedSheets (
        [&] (const Triangle& t) {
          const std::array<double, 3> n = areaNormal (t, positions);
          double facing = 0;
          for (int k = 0; k < 3; ++k)
            facing += n[k] * ((*viewpoint)[k] - (positions[t[0]][k] + positions[t[1]][k] + positions[t[2]][k]) / 3);
          return facing;
        },
        out_of_solid);
  return growth.orientedSheets ([&] (const Triangle& t) { return areaNormal (t, positions)[2]; }, out_of_solid);
}

} // namespace pcl_wrap::detail
