// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/wrap_filtration.h"

#include "util/parallel_for_each.h"
#include "wrap/removal_log.h"
#include "wrap/retraction.h"
#include "wrap/sink_deletion.h"

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>
#include <CGAL/Simple_cartesian.h>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>

namespace pcl_wrap::detail
{
namespace
{

using Interval = CGAL::Interval_nt<false>;
using IntervalKernel = CGAL::Simple_cartesian<Interval>;

/** Bounds on the squared radius of the smallest orthosphere of (k, s), in interval arithmetic;
  * the caller rounds upward. */
Interval
intervalSize (const SimplicialComplex& complex, Simplex s, const std::vector<Point3>& positions,
              const std::vector<double>& weights)
{
  static const IntervalKernel::Compute_squared_radius_smallest_orthogonal_sphere_3 radius{};
  const std::uint32_t* v = complex.vertices (s.dim, s.id);
  const auto point = [&] (int i) {
    const Point3& p = positions[v[i]];
    return IntervalKernel::Weighted_point_3 (IntervalKernel::Point_3 (p[0], p[1], p[2]), weights[v[i]]);
  };
  switch (s.dim)
  {
  case 0: return radius (point (0));
  case 1: return radius (point (0), point (1));
  case 2: return radius (point (0), point (1), point (2));
  default: return radius (point (0), point (1), point (2), point (3));
  }
}

/** The same size, exactly, as a fraction num / den (den > 0), in multiprecision floats: ring
  * operations only, no gcd, so it is cheap enough to order thousands of nearly equal sizes. With
  * q_i = p_i - p_0, G their Gram matrix and r_i = |q_i|^2 - w_i + w_0, the centre
  * p_0 + sum l_j q_j of the smallest orthosphere has 2 G l = r, and its squared radius is
  * r' adj(G) r / (4 det G) - w_0. */
struct SizeFraction
{
  CGAL::Mpzf num, den;
};

SizeFraction
sizeFraction (const SimplicialComplex& complex, Simplex s, const std::vector<Point3>& positions,
              const std::vector<double>& weights)
{
  using F = CGAL::Mpzf;
  const std::uint32_t* v = complex.vertices (s.dim, s.id);
  const int k = s.dim;
  std::array<std::array<F, 3>, 3> q;
  std::array<F, 3> r;
  for (int i = 1; i <= k; ++i)
  {
    F norm (0);
    for (int c = 0; c < 3; ++c)
    {
      q[i - 1][c] = F (positions[v[i]][c]) - F (positions[v[0]][c]);
      norm += q[i - 1][c] * q[i - 1][c];
    }
    r[i - 1] = norm - F (weights[v[i]]) + F (weights[v[0]]);
  }
  std::array<std::array<F, 3>, 3> g;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      g[i][j] = q[i][0] * q[j][0] + q[i][1] * q[j][1] + q[i][2] * q[j][2];
  F det (1), form (0); // det G and r' adj(G) r
  if (k == 1)
  {
    det = g[0][0];
    form = r[0] * r[0];
  }
  else if (k == 2)
  {
    det = g[0][0] * g[1][1] - g[0][1] * g[0][1];
    form = g[1][1] * r[0] * r[0] - F (2) * g[0][1] * r[0] * r[1] + g[0][0] * r[1] * r[1];
  }
  else if (k == 3)
  {
    std::array<std::array<F, 3>, 3> adj; // G is symmetric, so is its adjugate
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
      {
        const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
        adj[i][j] = g[i1][j1] * g[i2][j2] - g[i1][j2] * g[i2][j1];
      }
    det = g[0][0] * adj[0][0] + g[0][1] * adj[1][0] + g[0][2] * adj[2][0];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        form += r[i] * adj[i][j] * r[j];
  }
  return {form - F (4) * F (weights[v[0]]) * det, F (4) * det};
}

/** The sign of a.num / a.den - b.num / b.den. */
int
compareSizes (const SizeFraction& a, const SizeFraction& b)
{
  return Mpzf_cmp (a.num * b.den, b.num * a.den); // found by ADL
}

} // namespace

void
orderSinks (const SimplicialComplex& complex, const Classification& classification,
            const std::vector<Point3>& positions, const std::vector<double>& weights, WrapFiltration& filtration,
            double larger_than, std::size_t at_least)
{
  // One pass over the simplices on all threads bounds every sink's size in interval arithmetic
  // and keeps those that may belong to the prefix: an upper bound above larger_than, or one at
  // least the at_least-th largest lower bound (the at_least largest sizes are all at least that).
  // Each thread keeps its own at_least largest lower bounds; the at_least-th of them is at most
  // the overall one, so what it keeps is a superset, filtered at the end.
  struct Found
  {
    std::size_t sinks = 0;
    std::vector<double> top; // a min-heap of the at_least largest lower bounds
    std::vector<Simplex> kept;
    std::vector<Interval> kept_bounds;
  };
  tbb::enumerable_thread_specific<Found> found;
  for (int k = 0; k <= complex.dimension (); ++k)
    tbb::parallel_for (tbb::blocked_range<SimplexId> (0, static_cast<SimplexId> (complex.size (k)), 4096),
                       [&] (const tbb::blocked_range<SimplexId>& r) {
                         const CGAL::Protect_FPU_rounding<true> upward; // for the chunk's interval arithmetic
                         Found& f = found.local ();
                         for (SimplexId s = r.begin (); s != r.end (); ++s)
                         {
                           if (classification.classes[k][s] != SimplexClass::centered)
                             continue;
                           ++f.sinks;
                           const Interval b = intervalSize (complex, {k, s}, positions, weights);
                           if (at_least > 0 && (f.top.size () < at_least || b.inf () > f.top.front ()))
                           {
                             if (f.top.size () == at_least)
                             {
                               std::pop_heap (f.top.begin (), f.top.end (), std::greater<> ());
                               f.top.pop_back ();
                             }
                             f.top.push_back (b.inf ());
                             std::push_heap (f.top.begin (), f.top.end (), std::greater<> ());
                           }
                           // With at_least 0 the heap stays empty and only larger_than decides.
                           const bool may_be_in_top =
                               at_least > 0 && (f.top.size () < at_least || b.sup () >= f.top.front ());
                           if (b.sup () > larger_than || may_be_in_top)
                           {
                             f.kept.push_back ({k, s});
                             f.kept_bounds.push_back (b);
                           }
                         }
                       });
  std::vector<double> top;
  filtration.sink_count = 0;
  for (const Found& f : found)
  {
    filtration.sink_count += f.sinks;
    top.insert (top.end (), f.top.begin (), f.top.end ());
  }
  double lowest_top = std::numeric_limits<double>::infinity ();
  if (at_least > 0 && !top.empty ())
  {
    const std::size_t nth = std::min (at_least, top.size ()) - 1;
    std::nth_element (top.begin (), top.begin () + nth, top.end (), std::greater<> ());
    lowest_top = top[nth];
  }
  std::vector<Simplex> sinks;
  std::vector<Interval> bounds;
  for (const Found& f : found)
    for (std::size_t i = 0; i < f.kept.size (); ++i)
      if (f.kept_bounds[i].sup () > larger_than || f.kept_bounds[i].sup () >= lowest_top)
      {
        sinks.push_back (f.kept[i]);
        bounds.push_back (f.kept_bounds[i]);
      }

  // Bounds that overlap others' leave the order to exact sizes, computed here on all threads.
  // Sorted by lower bound, a bound overlaps a later one iff it reaches the next one, and an
  // earlier one iff the highest earlier upper bound reaches it.
  std::vector<std::size_t> by_lower (sinks.size ());
  std::iota (by_lower.begin (), by_lower.end (), 0);
  std::sort (by_lower.begin (), by_lower.end (),
             [&] (std::size_t a, std::size_t b) { return bounds[a].inf () < bounds[b].inf (); });
  std::vector<std::size_t> overlapping;
  double reach = -std::numeric_limits<double>::infinity ();
  for (std::size_t r = 0; r < by_lower.size (); ++r)
  {
    const Interval& b = bounds[by_lower[r]];
    if ((r + 1 < by_lower.size () && bounds[by_lower[r + 1]].inf () <= b.sup ()) || reach >= b.inf ())
      overlapping.push_back (by_lower[r]);
    reach = std::max (reach, b.sup ());
  }
  std::vector<std::optional<SizeFraction>> exact (sinks.size ());
  tbb::parallel_for (std::size_t (0), overlapping.size (), [&] (std::size_t i) {
    exact[overlapping[i]] = sizeFraction (complex, sinks[overlapping[i]], positions, weights);
  });

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
    if (bounds[a].inf () > bounds[b].sup () || bounds[b].inf () > bounds[a].sup ())
      return bounds[a].inf () > bounds[b].sup ();
    const int c = compareSizes (*exact[a], *exact[b]); // overlapping bounds: both computed
    return c != 0 ? c > 0 : coordinates (a) < coordinates (b);
  });

  // The prefix: the at_least first, then while larger than larger_than. A size is reported as
  // the middle of its bounds, lowered where needed to keep the reported sizes non-increasing
  // (bounds that overlap can have their middles the other way round).
  const auto larger = [&] (std::size_t i) {
    if (!std::isfinite (larger_than)) // every size is above -inf, none above +inf
      return larger_than < 0;
    if (bounds[i].inf () > larger_than || !(bounds[i].sup () > larger_than))
      return bounds[i].inf () > larger_than;
    if (!exact[i])
      exact[i] = sizeFraction (complex, sinks[i], positions, weights);
    return Mpzf_cmp (exact[i]->num, CGAL::Mpzf (larger_than) * exact[i]->den) > 0;
  };
  filtration.sinks.clear ();
  filtration.sink_sizes.clear ();
  for (std::size_t i : order)
  {
    if (filtration.sinks.size () >= at_least && !larger (i))
      break;
    const double middle = (bounds[i].inf () + bounds[i].sup ()) / 2;
    filtration.sinks.push_back (sinks[i]);
    filtration.sink_sizes.push_back (filtration.sink_sizes.empty () ? middle
                                                                    : std::min (middle, filtration.sink_sizes.back ()));
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
