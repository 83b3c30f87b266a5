// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "solid_labelling.h"

#include "parallel_for_each.h"
#include "regular_triangulation.h"

#include <algorithm>
#include <array>
#include <cmath>

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

/** Per tetrahedron: the tetrahedron across each facet (NO_NEIGHBOUR on the hull) and the vote
  * cast across it, in one half cache line. */
struct alignas (32) Facets
{
  std::uint32_t across[4];
  float vote[4];
};

/** Per tetrahedron: the strongest vote received so far for each side. */
struct Evidence
{
  float in = 0.0f, out = 0.0f;
};

constexpr std::uint8_t UNKNOWN = 0, INSIDE = 1, OUTSIDE = 2;
constexpr int BUCKETS = 4096;

int
bucketOf (float in, float out)
{
  return std::min (BUCKETS - 1, static_cast<int> (std::fabs (in - out) * BUCKETS));
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

SolidLabels
labelSolid (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours,
            const std::vector<Point3>& positions, const std::vector<double>& weights, const Retraction& x)
{
  const std::size_t n = complex.dimension () == 3 ? complex.size (3) : 0;
  FilledInParallel<Sphere> spheres (n);
  parallelForEach (n, [&] (std::size_t t) {
    spheres[t] = orthosphere (complex.vertices (3, static_cast<SimplexId> (t)), positions, weights);
  });

  // The vote of the sphere of t across its facet i for the other side: the cosine of the angle
  // at which the two spheres meet. Heights are taken along the facet's normal towards t's apex.
  const auto vote = [&] (std::uint32_t t, int i) -> double {
    const std::uint32_t* v = complex.vertices (3, t);
    const Point3& a = positions[v[(i + 1) & 3]];
    const Vec normal_raw =
        cross (minus (positions[v[(i + 2) & 3]], a), minus (positions[v[(i + 3) & 3]], a));
    const double length = std::sqrt (dot (normal_raw, normal_raw));
    if (!(length > 0) || !spheres[t].finite)
      return 0.0;
    Vec normal{normal_raw[0] / length, normal_raw[1] / length, normal_raw[2] / length};
    if (dot (normal, minus (positions[v[i]], a)) < 0)
      normal = {-normal[0], -normal[1], -normal[2]};
    const Vec to_t = minus (spheres[t].centre, a);
    const double ht = dot (to_t, normal);
    const double wa = weights[v[(i + 1) & 3]];
    const std::uint32_t u = neighbours[4 * std::size_t (t) + i];
    if (u == NO_NEIGHBOUR) // the outside: a half-space, its centre infinitely far below the facet
    {
      const double rho2 = dot (to_t, to_t) - ht * ht - wa;
      const double r = std::sqrt (rho2 + ht * ht);
      return r > 0 ? std::clamp (-ht / r, -1.0, 1.0) : 0.0;
    }
    if (!spheres[u].finite)
      return 0.0;
    const Vec to_u = minus (spheres[u].centre, a);
    const double hu = dot (to_u, normal);
    // The circle both spheres pass through, from the centre nearer the facet (less cancellation).
    const double rho2 = std::fabs (ht) <= std::fabs (hu) ? dot (to_t, to_t) - ht * ht - wa
                                                        : dot (to_u, to_u) - hu * hu - wa;
    return sphereAngleCosine (rho2, ht, hu);
  };
  // Every facet's vote, in parallel, before the (sequential) flood reads them, stored next to the
  // neighbour across it: the flood visits tetrahedra in priority order, all over the mesh, and
  // reads both at once. A vote is the same from both sides, so each interior facet is computed by
  // its lower-numbered tetrahedron and copied to the other.
  FilledInParallel<Facets> facets (n);
  parallelForEach (n, [&] (std::size_t t) {
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = neighbours[4 * t + i];
      facets[t].across[i] = u;
      if (u == NO_NEIGHBOUR || u > t)
        facets[t].vote[i] = static_cast<float> (vote (static_cast<std::uint32_t> (t), i));
    }
  });
  parallelForEach (n, [&] (std::size_t t) {
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = facets[t].across[i];
      if (u != NO_NEIGHBOUR && u < t)
        for (int j = 0; j < 4; ++j)
          if (neighbours[4 * std::size_t (u) + j] == t)
            facets[t].vote[i] = facets[u].vote[j];
    }
  });
  spheres = {};

  FilledInParallel<Evidence> evidence (n);
  FilledInParallel<std::uint8_t> label (n);
  parallelForEach (n, [&] (std::size_t t) {
    evidence[t] = {};
    label[t] = UNKNOWN;
  });
  std::vector<std::vector<std::uint32_t>> queue (BUCKETS);
  int top = -1;
  const auto cast = [&] (std::uint32_t t, std::uint8_t side, float strength) {
    Evidence& e = evidence[t];
    float& to = side == INSIDE ? e.in : e.out;
    if (strength <= to)
      return;
    to = strength;
    const int b = bucketOf (e.in, e.out);
    queue[b].push_back (t);
    top = std::max (top, b);
  };
  const auto other = [] (std::uint8_t side) { return side == INSIDE ? OUTSIDE : INSIDE; };

  for (std::uint32_t t = 0; t < n; ++t)
    for (int i = 0; i < 4; ++i)
      if (facets[t].across[i] == NO_NEIGHBOUR)
      {
        const float c = facets[t].vote[i];
        cast (t, c < 0 ? INSIDE : OUTSIDE, std::fabs (c));
      }

  while (top >= 0)
  {
    if (queue[top].empty ())
    {
      --top;
      continue;
    }
    const int b = top;
    const std::uint32_t t = queue[b].back ();
    queue[b].pop_back ();
    const Evidence e = evidence[t];
    if (label[t] != UNKNOWN || bucketOf (e.in, e.out) != b)
      continue; // labelled, or queued again at another priority
    label[t] = e.in > e.out ? INSIDE : e.out > e.in ? OUTSIDE : x.inY ({3, t}) ? INSIDE : OUTSIDE;
    const Facets& f = facets[t];
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = f.across[i];
      if (u == NO_NEIGHBOUR || label[u] != UNKNOWN)
        continue;
      const float c = f.vote[i];
      cast (u, c < 0 ? other (label[t]) : label[t], std::fabs (c));
    }
  }
  // A tetrahedron no vote reached (none on a connected triangulation) follows X.
  SolidLabels labels{std::vector<std::uint8_t> (n), std::vector<float> (n)};
  parallelForEach (n, [&] (std::size_t t) {
    labels.inside[t] = label[t] == INSIDE || (label[t] == UNKNOWN && x.inY ({3, static_cast<SimplexId> (t)}));
    labels.margin[t] = std::fabs (evidence[t].in - evidence[t].out);
  });
  const bool any_inside = std::find (labels.inside.begin (), labels.inside.end (), 1) != labels.inside.end ();
  // Every sphere voted for the outside (a few points, e.g. a box's corners around its centre): the
  // votes enclose nothing, and the solid is the convex hull.
  labels.hull = !any_inside;
  if (labels.hull)
    std::fill (labels.inside.begin (), labels.inside.end (), std::uint8_t (1));
  return labels;
}

} // namespace pcl_wrap::detail
