// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_reach.h"

#include "delaunay/cgal_kernel.h"

#include <CGAL/Interval_nt.h>

#include <algorithm>

namespace pcl_wrap::mpi
{
namespace
{

using Interval = CGAL::Interval_nt<false>;

detail::BarePoint
bare (const Point3& p)
{
  return {p[0], p[1], p[2]};
}

} // namespace

void
Box::add (const Point3& p)
{
  for (int c = 0; c < 3; ++c)
  {
    lo[c] = empty ? p[c] : std::min (lo[c], p[c]);
    hi[c] = empty ? p[c] : std::max (hi[c], p[c]);
  }
  empty = false;
}

int
Box::longestAxis () const
{
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (hi[c] - lo[c] > hi[axis] - lo[axis])
      axis = c;
  return axis;
}

double
Box::distance2 (const Point3& p) const
{
  double d2 = 0;
  for (int c = 0; c < 3; ++c)
  {
    const double gap = std::max ({0.0, lo[c] - p[c], p[c] - hi[c]});
    d2 += gap * gap;
  }
  return d2;
}

TileReach
TileReach::ofTetrahedron (const std::array<Point3, 4>& p, const std::array<double, 4>& w, double w_max)
{
  TileReach reach;
  Interval::Protector protect; // rounding towards +inf, as Interval_nt<false> needs
  // The orthocentre c solves 2 (p_i - p_0) . c = |p_i|^2 - |p_0|^2 - (w_i - w_0), i = 1..3;
  // Cramer's rule, every quantity an interval.
  Interval a[3][3], b[3];
  for (int i = 0; i < 3; ++i)
  {
    Interval norm_i = 0, norm_0 = 0;
    for (int c = 0; c < 3; ++c)
    {
      a[i][c] = 2 * (Interval (p[i + 1][c]) - p[0][c]);
      norm_i += Interval (p[i + 1][c]) * p[i + 1][c];
      norm_0 += Interval (p[0][c]) * p[0][c];
    }
    b[i] = norm_i - norm_0 - (Interval (w[i + 1]) - w[0]);
  }
  const auto det = [] (const Interval (&m)[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const Interval d = det (a);
  if (d.inf () <= 0 && d.sup () >= 0)
  {
    reach.everywhere_ = true;
    return reach;
  }
  Interval centre[3];
  for (int c = 0; c < 3; ++c)
  {
    Interval m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        m[i][j] = j == c ? b[i] : a[i][j];
    centre[c] = det (m) / d;
    reach.centre_lo_[c] = centre[c].inf ();
    reach.centre_hi_[c] = centre[c].sup ();
  }
  Interval r2 = -Interval (w[0]) + w_max;
  for (int c = 0; c < 3; ++c)
    r2 += CGAL::square (centre[c] - p[0][c]);
  reach.radius2_hi_ = r2.sup ();
  return reach;
}

TileReach
TileReach::ofHullFacet (const std::array<Point3, 3>& p, const Point3& inner)
{
  TileReach reach;
  reach.half_space_ = true;
  reach.facet_ = p;
  reach.inner_ = inner;
  return reach;
}

bool
TileReach::mayMeet (const Box& box) const
{
  if (box.empty)
    return false;
  if (everywhere_)
    return true;
  if (half_space_)
  {
    // A linear function is largest over a box at a corner: the half-space (closed) meets the
    // box iff a corner is on the plane or beyond it.
    const auto a = bare (facet_[0]), b = bare (facet_[1]), c = bare (facet_[2]);
    const CGAL::Orientation inside = CGAL::orientation (a, b, c, bare (inner_));
    for (int corner = 0; corner < 8; ++corner)
    {
      const Point3 q{corner & 1 ? box.hi[0] : box.lo[0], corner & 2 ? box.hi[1] : box.lo[1],
                     corner & 4 ? box.hi[2] : box.lo[2]};
      if (CGAL::orientation (a, b, c, bare (q)) != inside)
        return true;
    }
    return false;
  }
  // The squared distance from the centre to the box, bounded below, against r^2 + w_max.
  Interval::Protector protect;
  Interval distance2 = 0;
  for (int c = 0; c < 3; ++c)
  {
    const Interval centre (centre_lo_[c], centre_hi_[c]);
    const Interval below = Interval (box.lo[c]) - centre, above = centre - box.hi[c];
    const double gap = std::max ({0.0, below.inf (), above.inf ()});
    distance2 += Interval (gap) * gap;
  }
  return distance2.inf () <= radius2_hi_;
}

Point3
TileReach::centre () const
{
  Point3 q;
  for (int c = 0; c < 3; ++c)
    q[c] = std::clamp (centre_lo_[c] / 2 + centre_hi_[c] / 2, centre_lo_[c], centre_hi_[c]);
  return q;
}

bool
TileReach::mayMeetBeyond (const Point3& q, const Point3& nearest) const
{
  // Every point is at least |nearest - q| from q, so at least that less |q - c| from the true
  // centre c, which is in its bounds, as q is.
  Interval::Protector protect;
  Interval to_nearest2 = 0, q_off2 = 0;
  for (int c = 0; c < 3; ++c)
  {
    to_nearest2 += CGAL::square (Interval (nearest[c]) - q[c]);
    const double off = std::max ((Interval (centre_hi_[c]) - q[c]).sup (), (Interval (q[c]) - centre_lo_[c]).sup ());
    q_off2 += Interval (off) * off;
  }
  const Interval least = CGAL::sqrt (to_nearest2) - CGAL::sqrt (q_off2);
  return least.inf () <= 0 || (least * least).inf () <= radius2_hi_;
}

} // namespace pcl_wrap::mpi
