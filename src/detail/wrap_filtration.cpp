// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap_filtration.h"

#include "removal_log.h"
#include "retraction.h"
#include "sink_deletion.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

namespace pcl_wrap::detail
{
namespace
{

using ExactKernel = CGAL::Exact_predicates_exact_constructions_kernel;

/** The squared radius of the smallest orthosphere of (k, s), exactly (lazily). */
ExactKernel::FT
exactSize (const SimplicialComplex& complex, Simplex s, const std::vector<ExactKernel::Weighted_point_3>& points)
{
  static const ExactKernel::Compute_squared_radius_smallest_orthogonal_sphere_3 radius{};
  const std::uint32_t* v = complex.vertices (s.dim, s.id);
  switch (s.dim)
  {
  case 0: return radius (points[v[0]]);
  case 1: return radius (points[v[0]], points[v[1]]);
  case 2: return radius (points[v[0]], points[v[1]], points[v[2]]);
  default: return radius (points[v[0]], points[v[1]], points[v[2]], points[v[3]]);
  }
}

} // namespace

void
orderSinks (const SimplicialComplex& complex, const Classification& classification,
            const std::vector<Point3>& positions, const std::vector<double>& weights, WrapFiltration& filtration)
{
  std::vector<ExactKernel::Weighted_point_3> points;
  points.reserve (positions.size ());
  for (std::size_t i = 0; i < positions.size (); ++i)
    points.emplace_back (ExactKernel::Point_3 (positions[i][0], positions[i][1], positions[i][2]), weights[i]);

  std::vector<Simplex> sinks;
  std::vector<ExactKernel::FT> sizes;
  for (int k = 0; k <= complex.dimension (); ++k)
    for (SimplexId s = 0; s < complex.size (k); ++s)
      if (classification.classes[k][s] == SimplexClass::centered)
      {
        sinks.push_back ({k, s});
        sizes.push_back (exactSize (complex, {k, s}, points));
      }
  // Equal sizes: the sorted vertex coordinates decide, so the order depends on the points only.
  // Unused slots hold -inf: a shorter tuple compares as a prefix does, with no allocation.
  const auto coordinates = [&] (std::size_t i) {
    constexpr double LOW = -std::numeric_limits<double>::infinity ();
    std::array<Point3, 4> c;
    c.fill ({LOW, LOW, LOW});
    for (int j = 0; j <= sinks[i].dim; ++j)
      c[j] = positions[complex.vertex (sinks[i].dim, sinks[i].id, j)];
    std::sort (c.begin (), c.begin () + sinks[i].dim + 1);
    return c;
  };
  std::vector<std::size_t> order (sinks.size ());
  std::iota (order.begin (), order.end (), 0);
  std::sort (order.begin (), order.end (), [&] (std::size_t a, std::size_t b) {
    if (sizes[a] != sizes[b])
      return sizes[a] > sizes[b];
    return coordinates (a) < coordinates (b);
  });
  filtration.sinks.clear ();
  filtration.sink_sizes.clear ();
  for (std::size_t i : order)
  {
    filtration.sinks.push_back (sinks[i]);
    filtration.sink_sizes.push_back (CGAL::to_double (sizes[i]));
  }
}

WrapFiltration
wrapFiltration (const SimplicialComplex& complex, const Classification& classification,
                const std::vector<Point3>& positions, const std::vector<double>& weights, std::uint64_t order_seed)
{
  WrapFiltration f;
  orderSinks (complex, classification, positions, weights, f);

  // Stamp 1: the basic construction (omega); stamp j + 2: the deletion of sink j.
  Subcomplex y (complex);
  RemovalLog log (complex);
  Retraction retraction (y, classification, &log);
  log.stampRemovals (1);
  retraction.retract (order_seed);
  f.not_principal = deleteSinksGlobally (
      retraction, f, [] (std::size_t, double) { return true; },
      [&] (std::size_t j) { log.stampRemovals (static_cast<std::uint32_t> (j + 2)); }, f.deletions, order_seed);
  constexpr double INF = std::numeric_limits<double>::infinity ();
  for (int k = 0; k <= 3; ++k)
  {
    f.value[k].resize (complex.size (k));
    for (SimplexId s = 0; s < complex.size (k); ++s)
    {
      const std::uint32_t stamp = log.stamp ({k, s});
      f.value[k][s] = stamp == 0 ? -INF : stamp == 1 ? INF : f.sink_sizes[stamp - 2];
    }
  }
  return f;
}

} // namespace pcl_wrap::detail
