// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "power_predicates.h"

#include "cgal_kernel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pcl_wrap::detail
{

struct PowerPredicates::Points
{
  std::vector<WeightedPoint> points;
};

namespace
{

/** +1 inside, 0 on, -1 outside the smallest orthosphere of s[0..n-1]; exact. */
int
boundedSide (const WeightedPoint* const* s, int n, const WeightedPoint& q)
{
  static const Kernel::Power_side_of_bounded_power_sphere_3 side{};
  switch (n)
  {
  case 1: return side (*s[0], q);
  case 2: return side (*s[0], *s[1], q);
  case 3: return side (*s[0], *s[1], *s[2], q);
  case 4: return side (*s[0], *s[1], *s[2], *s[3], q);
  default: throw std::invalid_argument ("insideSmallestOrthosphere: 1 to 4 sphere points");
  }
}

/** A weight strictly larger than w, computed exactly (any increase will do: the predicate is
  * affine in the weight, so only the sign of the change matters). */
double
bumped (double w)
{
  const double up = w == 0.0 ? 1.0 : w + std::abs (w);
  return std::isfinite (up) && up > w ? up : std::nextafter (w, std::numeric_limits<double>::infinity ());
}

} // namespace

PowerPredicates::PowerPredicates (const std::vector<Point3>& positions, const std::vector<double>& weights)
  : points_ (std::make_unique<Points> ())
{
  points_->points.reserve (positions.size ());
  for (std::size_t i = 0; i < positions.size (); ++i)
  {
    const Point3& p = positions[i];
    points_->points.emplace_back (BarePoint (p[0], p[1], p[2]), weights[i]);
    uniform_weights_ = uniform_weights_ && weights[i] == weights[0];
  }
}

PowerPredicates::~PowerPredicates () = default;

bool
PowerPredicates::insideSmallestOrthosphere (const std::uint32_t* sphere, int n, std::uint32_t q) const
{
  const auto& pts = points_->points;
  const WeightedPoint* s[4];
  for (int i = 0; i < n; ++i)
    s[i] = &pts[sphere[i]];
  const int side = boundedSide (s, n, pts[q]);
  if (side != 0)
    return side > 0;

  // A tie: decide it for the perturbed weights w_i - eps_i. The largest eps whose coefficient is
  // not zero dominates; the coefficient's sign is that of the predicate with the weight bumped
  // up, and lowering the weight (the perturbation) gives the opposite sign.
  perturbations_.fetch_add (1, std::memory_order_relaxed);
  std::uint32_t order[5];
  std::copy (sphere, sphere + n, order);
  order[n] = q;
  std::sort (order, order + n + 1, [&] (std::uint32_t a, std::uint32_t b) {
    return CGAL::compare_xyz (pts[a].point (), pts[b].point ()) == CGAL::LARGER;
  });
  for (int k = 0; k <= n; ++k)
  {
    const std::uint32_t j = order[k];
    const WeightedPoint moved (pts[j].point (), bumped (pts[j].weight ()));
    const WeightedPoint* t[4];
    for (int i = 0; i < n; ++i)
      t[i] = sphere[i] == j ? &moved : s[i];
    const int bumped_side = boundedSide (t, n, q == j ? moved : pts[q]);
    if (bumped_side != 0)
      return bumped_side < 0;
  }
  // Unreachable: the query's own coefficient is never zero.
  throw std::logic_error ("insideSmallestOrthosphere: perturbation did not decide");
}

} // namespace pcl_wrap::detail
