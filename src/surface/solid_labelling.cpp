// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_labelling.h"

#include "util/parallel_for_each.h"
#include "util/portable.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>

namespace pcl_wrap::detail
{
namespace
{

using Vec = std::array<double, 3>;

Vec
minus (const Vec& a, const Vec& b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

double
dot (const Vec& a, const Vec& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec
cross (const Vec& a, const Vec& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/** A tetrahedron's orthosphere: the sphere orthogonal to its four weighted points. */
struct Sphere
{
  Vec centre;
  bool finite; // false for a tetrahedron too flat for its centre to be computed
};

Sphere
orthosphere (const std::uint32_t* v, const std::vector<Point3>& p, const std::vector<double>& w)
{
  // Relative to the first vertex: 2 a_i . c = |a_i|^2 - (w_i - w_0), solved by Cramer's rule.
  const Vec a1 = minus (p[v[1]], p[v[0]]), a2 = minus (p[v[2]], p[v[0]]), a3 = minus (p[v[3]], p[v[0]]);
  const double b1 = dot (a1, a1) - (w[v[1]] - w[v[0]]);
  const double b2 = dot (a2, a2) - (w[v[2]] - w[v[0]]);
  const double b3 = dot (a3, a3) - (w[v[3]] - w[v[0]]);
  const Vec c23 = cross (a2, a3), c31 = cross (a3, a1), c12 = cross (a1, a2);
  const double det = 2 * dot (a1, c23);
  Sphere s{};
  for (int k = 0; k < 3; ++k)
    s.centre[k] = (b1 * c23[k] + b2 * c31[k] + b3 * c12[k]) / det + p[v[0]][k];
  s.finite = std::isfinite (s.centre[0]) && std::isfinite (s.centre[1]) && std::isfinite (s.centre[2]);
  return s;
}

constexpr double VOTE_ONE = 32767; // a cosine of 1 in fixed point
constexpr std::size_t VOTE_BLOCK = 4096; // tetrahedra voted together, their spheres kept
constexpr std::uint8_t UNKNOWN = 0, INSIDE = 1, OUTSIDE = 2, TIED = 3;

int
bucketOf (std::uint16_t in, std::uint16_t out)
{
  return std::abs (int (in) - int (out)) >> 3; // 32767 >> 3: the last bucket
}

} // namespace

std::array<std::vector<std::uint8_t>, 4>
solidSubcomplex (const SimplicialComplex& complex, const std::vector<std::uint8_t>& inside)
{
  std::array<std::vector<std::uint8_t>, 4> in_solid;
  for (int k = 0; k <= 3; ++k)
    in_solid[k].assign (complex.size (k), 0);
  for (SimplexId t = 0; t < inside.size (); ++t)
    if (inside[t])
      for (unsigned mask = 1; mask < 16; ++mask)
      {
        const Simplex f = complex.face (3, t, mask);
        in_solid[f.dim][f.id] = 1;
      }
  return in_solid;
}

double
sphereAngleCosine (double rho2, double ha, double hb)
{
  const double c = (rho2 + ha * hb) / std::sqrt ((rho2 + ha * ha) * (rho2 + hb * hb));
  return std::isfinite (c) ? std::clamp (c, -1.0, 1.0) : 0.0;
}

SolidLabelling::SolidLabelling (const FilledInParallel<std::uint32_t>& tetrahedra, const Tetrahedra& adjacency,
                                const std::vector<Point3>& positions, const std::vector<double>& weights)
  : adjacency_ (adjacency), tets_ (tetrahedra.size () / 4), labelled_ ((tets_.size () + 63) / 64), queue_ (BUCKETS)
{
  const std::size_t n = tets_.size ();
  const auto vertices = [&] (std::size_t t) { return &tetrahedra[4 * t]; };

  // The vote of the sphere of t across its facet i for the other side: the cosine of the angle
  // at which the two spheres meet. Heights are taken along the facet's normal towards t's apex.
  // sphereOf (t) is the orthosphere of tetrahedron t.
  const auto vote = [&] (std::size_t t, int i, const auto& sphereOf) -> double {
    const std::uint32_t* v = vertices (t);
    const Point3& a = positions[v[(i + 1) & 3]];
    const Vec normal_raw =
        cross (minus (positions[v[(i + 2) & 3]], a), minus (positions[v[(i + 3) & 3]], a));
    const double length = std::sqrt (dot (normal_raw, normal_raw));
    const Sphere& st = sphereOf (t);
    if (!(length > 0) || !st.finite)
      return 0.0;
    Vec normal{normal_raw[0] / length, normal_raw[1] / length, normal_raw[2] / length};
    if (dot (normal, minus (positions[v[i]], a)) < 0)
      normal = {-normal[0], -normal[1], -normal[2]};
    const Vec to_t = minus (st.centre, a);
    const double ht = dot (to_t, normal);
    const double wa = weights[v[(i + 1) & 3]];
    const std::uint32_t u = adjacency.neighbour (static_cast<std::uint32_t> (t), i);
    if (u == OUTSIDE_HULL) // the outside: a half-space, its centre infinitely far below the facet
    {
      const double rho2 = dot (to_t, to_t) - ht * ht - wa;
      const double r = std::sqrt (rho2 + ht * ht);
      return r > 0 ? std::clamp (-ht / r, -1.0, 1.0) : 0.0;
    }
    const Sphere su = sphereOf (u);
    if (!su.finite)
      return 0.0;
    const Vec to_u = minus (su.centre, a);
    const double hu = dot (to_u, normal);
    // The circle both spheres pass through, from the centre nearer the facet (less cancellation).
    const double rho2 = std::fabs (ht) <= std::fabs (hu) ? dot (to_t, to_t) - ht * ht - wa
                                                        : dot (to_u, to_u) - hu * hu - wa;
    return sphereAngleCosine (rho2, ht, hu);
  };
  // A vote is the same from both sides: each interior facet's is computed by its lower-numbered
  // tetrahedron, which writes it into the other's record too (into a field that only it writes).
  // The tetrahedra are taken in blocks, whose spheres are computed once and kept while the block
  // is voted; a neighbour's outside the block is computed again (the same arithmetic, the same
  // sphere). The tetrahedra are numbered along a space-filling curve, so most neighbours are in
  // the block, and no array of every sphere is written to memory and read back.
  tbb::enumerable_thread_specific<std::vector<Sphere>> block_spheres;
  parallelForEach ((n + VOTE_BLOCK - 1) / VOTE_BLOCK,
                   [&] (std::size_t block) {
                     const std::size_t first = block * VOTE_BLOCK, last = std::min (n, first + VOTE_BLOCK);
                     std::vector<Sphere>& spheres = block_spheres.local ();
                     spheres.resize (last - first);
                     for (std::size_t t = first; t < last; ++t)
                       spheres[t - first] = orthosphere (vertices (t), positions, weights);
                     const auto sphereOf = [&] (std::size_t t) {
                       return t >= first && t < last ? spheres[t - first]
                                                     : orthosphere (vertices (t), positions, weights);
                     };
                     for (std::size_t t = first; t < last; ++t)
                     {
                       Record& r = tets_[t];
                       r.in = r.out = 0;
                       r.label = UNKNOWN;
                       for (int i = 0; i < 4; ++i)
                       {
                         const std::uint32_t u = adjacency.neighbour (static_cast<std::uint32_t> (t), i);
                         if (u != OUTSIDE_HULL && u < t)
                           continue;
                         const double cosine = vote (t, i, sphereOf);
                         const double weighed = cosine > 0 ? SAME_SIDE_WEIGHT * cosine : cosine;
                         r.vote[i] = static_cast<std::int16_t> (std::lrint (weighed * VOTE_ONE));
                         if (u != OUTSIDE_HULL)
                           tets_[u].vote[adjacency.mirrorIndex (static_cast<std::uint32_t> (t), i)] = r.vote[i];
                       }
                     }
                   },
                   1);
  // Where the flood starts, found here on all threads rather than by the flood's one.
  on_hull_ = indicesWhere (n, [&] (std::size_t t) { return adjacency.onHull (static_cast<std::uint32_t> (t)); });
}

void
SolidLabelling::cast (std::uint32_t t, std::uint8_t side, int vote)
{
  Record& r = tets_[t];
  const auto strength = static_cast<std::uint16_t> (std::abs (vote));
  std::uint16_t& to = side == INSIDE ? r.in : r.out;
  if (strength <= to)
    return;
  to = strength;
  const int b = bucketOf (r.in, r.out);
  queue_[b].push_back (t);
  // Pushed on the top bucket, it is often the next popped: its neighbours are on their way.
  prefetch (&adjacency_.neighbourArray ()[4 * std::size_t (t)]);
  top_ = std::max (top_, b);
}

void
SolidLabelling::castFrom (std::uint32_t t)
{
  const Record& r = tets_[t];
  const std::uint8_t other = r.label == INSIDE ? OUTSIDE : INSIDE;
  for (int i = 0; i < 4; ++i)
  {
    const std::uint32_t u = adjacency_.neighbour (t, i);
    if (u != OUTSIDE_HULL && !labelled (u))
      cast (u, r.vote[i] < 0 ? other : r.label, r.vote[i]);
  }
}

void
SolidLabelling::prefetchNextPops (const std::vector<std::uint32_t>& bucket) const
{
  // The flood jumps all over the mesh, and each tetrahedron it pops costs a few cache misses: its
  // record and neighbours, then its neighbours' records. A bucket is a stack, so the tetrahedra
  // popped next are mostly known: the record and neighbours of the eighth next are fetched, and
  // the neighbours' records of the fourth next, whose neighbours were fetched four pops ago (none
  // of what is labelled already: it is only skipped).
  if (bucket.size () < 8)
    return;
  const std::uint32_t later = bucket[bucket.size () - 8];
  if (!labelled (later))
  {
    prefetch (&tets_[later]);
    prefetch (&adjacency_.neighbourArray ()[4 * std::size_t (later)]);
  }
  const std::uint32_t soon = bucket[bucket.size () - 4];
  if (labelled (soon))
    return;
  for (int i = 0; i < 4; ++i)
  {
    const std::uint32_t u = adjacency_.neighbour (soon, i);
    if (u != OUTSIDE_HULL && !labelled (u))
      prefetch (&tets_[u]);
  }
}

void
SolidLabelling::run (const Subcomplex* x)
{
  while (top_ >= 0)
  {
    std::vector<std::uint32_t>& bucket = queue_[top_];
    if (bucket.empty ())
    {
      --top_;
      continue;
    }
    const int b = top_;
    const std::uint32_t t = bucket.back ();
    bucket.pop_back ();
    prefetchNextPops (bucket);
    if (labelled (t))
      continue;
    Record& r = tets_[t];
    if (bucketOf (r.in, r.out) != b)
      continue; // queued again at another priority
    markLabelled (t);
    if (r.in == r.out && !x)
    {
      r.label = TIED; // for X to break, when it is known
      tied_.push_back (t);
      continue;
    }
    r.label = r.in > r.out ? INSIDE : r.out > r.in ? OUTSIDE : x->contains ({3, t}) ? INSIDE : OUTSIDE;
    castFrom (t);
  }
}

void
SolidLabelling::flood ()
{
  for (std::uint32_t t : on_hull_)
    for (int i = 0; i < 4; ++i)
      if (adjacency_.neighbour (t, i) == OUTSIDE_HULL)
        cast (t, tets_[t].vote[i] < 0 ? INSIDE : OUTSIDE, tets_[t].vote[i]);
  std::vector<std::uint32_t> ().swap (on_hull_);
  run (nullptr);
  std::vector<std::vector<std::uint32_t>> (BUCKETS).swap (queue_); // every bucket is empty: free them
  // With no tie for X to break, the labels are final: kept in 5 bytes per tetrahedron instead of
  // the flood's 16 while X is computed.
  const auto reached = [&] { // by some vote: every tetrahedron of a connected triangulation is
    for (const Record& r : tets_)
      if (r.label == UNKNOWN)
        return false;
    return true;
  };
  if (tied_.empty () && reached ())
  {
    finished_ = labelsOf (nullptr);
    FilledInParallel<Record> ().swap (tets_);
    std::vector<std::uint64_t> ().swap (labelled_);
  }
}

SolidLabels
SolidLabelling::labelsOf (const Subcomplex* x) const
{
  // A tetrahedron no vote reached (none on a connected triangulation) follows X.
  const std::size_t n = tets_.size ();
  SolidLabels labels{std::vector<std::uint8_t> (n), std::vector<float> (n)};
  parallelForEach (n, [&] (std::size_t t) {
    const Record& r = tets_[t];
    labels.inside[t] = r.label == INSIDE || (r.label == UNKNOWN && x && x->contains ({3, static_cast<SimplexId> (t)}));
    labels.margin[t] = static_cast<float> (std::abs (int (r.in) - int (r.out)) / VOTE_ONE);
  });
  return labels;
}

SolidLabels
SolidLabelling::labels (const Subcomplex& x)
{
  SolidLabels labels;
  if (finished_)
    labels = std::move (*finished_);
  else
  {
    // Ties are votes of exactly equal strength, the last the flood reaches: broken by X, and the
    // flood finished from them.
    for (std::uint32_t t : tied_)
    {
      tets_[t].label = x.contains ({3, t}) ? INSIDE : OUTSIDE;
      castFrom (t);
    }
    tied_.clear ();
    run (&x);
    labels = labelsOf (&x);
  }
  const bool any_inside = std::find (labels.inside.begin (), labels.inside.end (), 1) != labels.inside.end ();
  // Every sphere voted for the outside (a few points, e.g. a box's corners around its centre): the
  // votes enclose nothing, and the solid is the convex hull.
  labels.hull = !any_inside;
  if (labels.hull)
    std::fill (labels.inside.begin (), labels.inside.end (), std::uint8_t (1));
  return labels;
}

} // namespace pcl_wrap::detail
