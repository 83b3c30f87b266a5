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
constexpr std::size_t VOTE_BLOCK = 4096;        // tetrahedra voted together, their spheres kept
constexpr std::uint8_t INSIDE = 1, OUTSIDE = 2; // the side a vote is cast for

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
  : adjacency_ (adjacency),
    votes_ (tetrahedra.size () / 4),
    strongest_ (votes_.size ()),
    labelled_ ((votes_.size () + 63) / 64),
    inside_ (labelled_.size ())
{
  const std::size_t n = votes_.size ();
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
  // tetrahedron, which writes it into the other's votes too (into a slot that only it writes).
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
                       Votes& r = votes_[t];
                       strongest_[t] = {0, 0};
                       for (int i = 0; i < 4; ++i)
                       {
                         const std::uint32_t u = adjacency.neighbour (static_cast<std::uint32_t> (t), i);
                         if (u != OUTSIDE_HULL && u < t)
                           continue;
                         const double cosine = vote (t, i, sphereOf);
                         const double weighed = cosine > 0 ? SAME_SIDE_WEIGHT * cosine : cosine;
                         r[i] = static_cast<std::int16_t> (std::lrint (weighed * VOTE_ONE));
                         if (u != OUTSIDE_HULL)
                           votes_[u][adjacency.mirrorIndex (static_cast<std::uint32_t> (t), i)] = r[i];
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
  Strongest& r = strongest_[t];
  const auto strength = static_cast<std::uint16_t> (std::abs (vote));
  std::uint16_t& to = side == INSIDE ? r.in : r.out;
  if (strength <= to)
    return;
  to = strength;
  queue_.push (bucketOf (r.in, r.out), t);
  // Pushed on the top bucket, it is often the next popped: its neighbours are on their way.
  prefetch (&adjacency_.neighbourArray ()[4 * std::size_t (t)]);
}

void
SolidLabelling::castFrom (std::uint32_t t)
{
  const Votes& vote = votes_[t];
  const std::uint8_t label = inside (t) ? INSIDE : OUTSIDE, other = label == INSIDE ? OUTSIDE : INSIDE;
  for (int i = 0; i < 4; ++i)
  {
    const std::uint32_t u = adjacency_.neighbour (t, i);
    if (u != OUTSIDE_HULL && !labelled (u))
      cast (u, vote[i] < 0 ? other : label, vote[i]);
  }
}

void
SolidLabelling::prefetchNextPops (const std::vector<std::uint32_t>& bucket) const
{
  // The flood jumps all over the mesh, and each tetrahedron it pops costs a few cache misses: its
  // strongest votes, votes and neighbours, then its neighbours' strongest votes. A bucket is a
  // stack, so the tetrahedra popped next are mostly known: what the eighth next reads of itself is
  // fetched, and the neighbours' strongest votes of the fourth next, whose neighbours were fetched
  // four pops ago (none of what is labelled already: it is only skipped).
  if (bucket.size () < 8)
    return;
  const std::uint32_t later = bucket[bucket.size () - 8];
  if (!labelled (later))
  {
    prefetch (&strongest_[later]);
    prefetch (&votes_[later]);
    prefetch (&adjacency_.neighbourArray ()[4 * std::size_t (later)]);
  }
  const std::uint32_t soon = bucket[bucket.size () - 4];
  if (labelled (soon))
    return;
  for (int i = 0; i < 4; ++i)
  {
    const std::uint32_t u = adjacency_.neighbour (soon, i);
    if (u != OUTSIDE_HULL && !labelled (u))
      prefetch (&strongest_[u]);
  }
}

void
SolidLabelling::run (const Subcomplex* x)
{
  for (int b = queue_.top (); b >= 0; b = queue_.top ())
  {
    const std::uint32_t t = queue_.pop (b);
    prefetchNextPops (queue_.stack (b));
    if (labelled (t))
      continue;
    const Strongest r = strongest_[t];
    if (bucketOf (r.in, r.out) != b)
      continue; // queued again at another priority
    setBit (labelled_, t);
    if (r.in == r.out && !x)
    {
      tied_.push_back (t); // for X to break, when it is known
      continue;
    }
    if (r.in > r.out || (r.in == r.out && x->contains ({3, t})))
      setBit (inside_, t);
    castFrom (t);
  }
}

void
SolidLabelling::flood ()
{
  for (std::uint32_t t : on_hull_)
    for (int i = 0; i < 4; ++i)
      if (adjacency_.neighbour (t, i) == OUTSIDE_HULL)
        cast (t, votes_[t][i] < 0 ? INSIDE : OUTSIDE, votes_[t][i]);
  std::vector<std::uint32_t> ().swap (on_hull_);
  run (nullptr);
  queue_.release ();
  // With no tie for X to break, the labels are final: kept in 5 bytes per tetrahedron instead of
  // the flood's 12 while X is computed.
  const auto reached = [&] { // by some vote: every tetrahedron of a connected triangulation is
    const std::size_t n = votes_.size ();
    for (std::size_t k = 0; k < n / 64; ++k)
      if (~labelled_[k])
        return false;
    for (std::size_t t = n & ~std::size_t (63); t < n; ++t)
      if (!labelled (static_cast<std::uint32_t> (t)))
        return false;
    return true;
  };
  if (tied_.empty () && reached ())
  {
    FilledInParallel<Votes> ().swap (votes_);
    finished_ = labelsOf (nullptr);
    FilledInParallel<Strongest> ().swap (strongest_);
    std::vector<std::uint64_t> ().swap (labelled_);
    std::vector<std::uint64_t> ().swap (inside_);
  }
}

SolidLabels
SolidLabelling::labelsOf (const Subcomplex* x) const
{
  // A tetrahedron no vote reached (none on a connected triangulation) follows X.
  const std::size_t n = strongest_.size ();
  SolidLabels labels{std::vector<std::uint8_t> (n), std::vector<float> (n)};
  parallelForEach (n, [&] (std::size_t t) {
    const Strongest& r = strongest_[t];
    const auto id = static_cast<std::uint32_t> (t);
    labels.inside[t] = labelled (id) ? inside (id) : x && x->contains ({3, static_cast<SimplexId> (t)});
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
      if (x.contains ({3, t}))
        setBit (inside_, t);
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
