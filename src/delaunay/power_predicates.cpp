// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "delaunay/power_predicates.h"

#include "delaunay/cgal_kernel.h"
#include "util/huge_pages.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pcl_wrap::detail
{

struct PowerPredicates::Points
{
  HugePageVector<WeightedPoint> points; // read at random, by vertex id
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

// The static filters below trust double arithmetic only when every non-zero coordinate
// difference lies in [2^-120, 2^120]: then no product of up to six of them, nor any rounded
// difference of such products, leaves the normal range, and the relative error bounds hold.
bool
inFilterRange (const double* x, int n)
{
  for (int i = 0; i < n; ++i)
  {
    const double m = std::abs (x[i]);
    if (m != 0.0 && !(m >= 0x1p-120 && m <= 0x1p120))
      return false;
  }
  return true;
}

double
dot (const double* x, const double* y)
{
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

/** x times y; with \a absolute, the same formula over |x|, |y| with every minus a plus (the
  * magnitude that bounds the rounding error). */
void
cross (const double* x, const double* y, double* out, bool absolute = false)
{
  const double s = absolute ? 1.0 : -1.0;
  out[0] = x[1] * y[2] + s * x[2] * y[1];
  out[1] = x[2] * y[0] + s * x[0] * y[2];
  out[2] = x[0] * y[1] + s * x[1] * y[0];
}

/** The sign of a polynomial \a value computed in doubles when it is certain: \a magnitude is the
  * same polynomial over absolute values with every minus a plus, and \a depth bounds the number
  * of roundings along any path from a coordinate difference to the result. Every monomial then
  * carries at most depth factors (1 + delta), |delta| <= 2^-53, so the error is below
  * 2 depth 2^-53 magnitude (the factor 2 covers the rounding of magnitude itself). */
int
certainSign (double value, double magnitude, int depth)
{
  const double bound = 2.0 * depth * 0x1p-53 * magnitude;
  return value > bound ? 1 : value < -bound ? -1 : 0;
}

/** With equal weights the smallest orthosphere of an edge ab is its diametral sphere, and q is
  * strictly inside it iff (q - a).(q - b) < 0. Returns that sign (-1 inside, +1 outside) when
  * double arithmetic certainly has it right, 0 when the exact predicate must decide. */
int
diametralSideFiltered (const BarePoint& a, const BarePoint& b, const BarePoint& q)
{
  double x[3], y[3];
  for (int i = 0; i < 3; ++i)
    x[i] = q[i] - a[i], y[i] = q[i] - b[i];
  if (!inFilterRange (x, 3) || !inFilterRange (y, 3))
    return 0;
  double magnitude = 0.0;
  for (int i = 0; i < 3; ++i)
    magnitude += std::abs (x[i] * y[i]);
  return certainSign (dot (x, y), magnitude, 4);
}

/** With equal weights the smallest orthosphere of a triangle abc is the sphere through its
  * circumcircle, centred at o = a + (m x n) / (2 |n|^2) with u = b - a, v = c - a, n = u x v,
  * m = |u|^2 v - |v|^2 u. With w = q - a, q is strictly inside iff |w - (o - a)|^2 < |o - a|^2,
  * that is iff |w|^2 |n|^2 - w.(m x n) < 0 (times |n|^2 > 0). The sign as above. */
int
circumsphereSideFiltered (const BarePoint& a, const BarePoint& b, const BarePoint& c, const BarePoint& q)
{
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; ++i)
    u[i] = b[i] - a[i], v[i] = c[i] - a[i], w[i] = q[i] - a[i];
  if (!inFilterRange (u, 3) || !inFilterRange (v, 3) || !inFilterRange (w, 3))
    return 0;
  double n[3], m[3], mn[3];
  cross (u, v, n);
  const double uu = dot (u, u), vv = dot (v, v);
  for (int i = 0; i < 3; ++i)
    m[i] = uu * v[i] - vv * u[i];
  cross (m, n, mn);
  const double value = dot (w, w) * dot (n, n) - dot (w, mn);

  double au[3], av[3], aw[3], an[3], am[3], amn[3];
  for (int i = 0; i < 3; ++i)
    au[i] = std::abs (u[i]), av[i] = std::abs (v[i]), aw[i] = std::abs (w[i]);
  cross (au, av, an, true);
  for (int i = 0; i < 3; ++i)
    am[i] = uu * av[i] + vv * au[i];
  cross (am, an, amn, true);
  const double magnitude = dot (aw, aw) * dot (an, an) + dot (aw, amn);
  // Depth: difference 1, |u|^2 3 more, m 2 more, m x n 2 more, dot with w 3 more, the final
  // difference 1: 12.
  return certainSign (value, magnitude, 12);
}

/** circumsphereSideFiltered for each vertex p_i of a tetrahedron against the facet opposite it,
  * into \a sign[i], all four from one circumcentre. With equal weights p_i is inside the
  * smallest orthosphere of the opposite facet iff the tetrahedron's circumcentre lies beyond that
  * facet, that is iff its barycentric coordinate lambda_i is negative. With u_j = p_j - p_0,
  * c_1 = u_2 x u_3, c_2 = u_3 x u_1, c_3 = u_1 x u_2, D = u_1 . c_1 and
  * N = |u_1|^2 c_1 + |u_2|^2 c_2 + |u_3|^2 c_3, the circumcentre is p_0 + N / (2 D), so
  * lambda_j = N . c_j / (2 D^2) for j = 1..3 and lambda_0 = (2 D^2 - sum_j N . c_j) / (2 D^2):
  * the signs of N . c_j and of 2 D^2 - sum_j N . c_j. Each is trusted as in certainSign; an
  * undecided one is 0 (the exact predicate decides it), and all are 0 when a difference u_j is
  * outside the filter's range. */
void
tetrahedronSidesFiltered (const BarePoint& p0, const BarePoint& p1, const BarePoint& p2, const BarePoint& p3, int* sign)
{
  const BarePoint* p[4] = {&p0, &p1, &p2, &p3};
  double u[4][3], au[4][3];
  for (int j = 1; j < 4; ++j)
  {
    for (int c = 0; c < 3; ++c)
      u[j][c] = (*p[j])[c] - p0[c], au[j][c] = std::abs (u[j][c]);
    if (!inFilterRange (u[j], 3))
      return;
  }
  // Cross products c_j (and over absolute values) of the other two, cyclically.
  double cr[4][3], acr[4][3];
  for (int j = 1; j < 4; ++j)
  {
    const int k = j % 3 + 1, l = k % 3 + 1;
    cross (u[k], u[l], cr[j]);
    cross (au[k], au[l], acr[j], true);
  }
  const double uu[4] = {0.0, dot (u[1], u[1]), dot (u[2], u[2]), dot (u[3], u[3])};
  double n[3], an[3];
  for (int c = 0; c < 3; ++c)
  {
    n[c] = uu[1] * cr[1][c] + uu[2] * cr[2][c] + uu[3] * cr[3][c];
    an[c] = uu[1] * acr[1][c] + uu[2] * acr[2][c] + uu[3] * acr[3][c];
  }
  const double d = dot (u[1], cr[1]), ad = dot (au[1], acr[1]);
  double sum = 0.0, asum = 0.0;
  for (int j = 1; j < 4; ++j)
  {
    const double l = dot (n, cr[j]), al = dot (an, acr[j]);
    // Depth: difference 1, cross product 2 more, |u|^2 c 1 more over |u|^2's 4, N's sums 2
    // more: 7; the dot with c_j 3 more: 10.
    sign[j] = certainSign (l, al, 10);
    sum += l, asum += al;
  }
  // Depth: D is 6 (difference, cross, dot), D^2 7; the sum of the three 12; the difference 13.
  sign[0] = certainSign (2.0 * d * d - sum, 2.0 * ad * ad + asum, 13);
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
  if (uniform_weights_ && (n == 2 || n == 3))
  {
    const BarePoint& p = pts[q].point ();
    const int sign = n == 2 ? diametralSideFiltered (pts[sphere[0]].point (), pts[sphere[1]].point (), p)
                            : circumsphereSideFiltered (pts[sphere[0]].point (), pts[sphere[1]].point (),
                                                        pts[sphere[2]].point (), p);
    if (sign != 0)
      return sign < 0;
  }
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

unsigned
PowerPredicates::insideOppositeFacets (const std::uint32_t* v, int k) const
{
  const auto& pts = points_->points;
  // A tetrahedron's four answers come from one filter, a triangle's from the diametral filter
  // asked here inline (the hot path; leaving it to the call below measured no faster). What
  // they cannot decide goes to insideSmallestOrthosphere, whose own filters run again before
  // the exact way: repeated work, but only for the rare undecided questions.
  int tetrahedron[4] = {0, 0, 0, 0};
  if (uniform_weights_ && k == 3)
    tetrahedronSidesFiltered (pts[v[0]].point (), pts[v[1]].point (), pts[v[2]].point (), pts[v[3]].point (),
                              tetrahedron);
  unsigned inside = 0;
  for (int i = 0; i <= k; ++i)
  {
    std::uint32_t facet[3];
    int n = 0;
    for (int j = 0; j <= k; ++j)
      if (j != i)
        facet[n++] = v[j];
    int sign = tetrahedron[i];
    if (uniform_weights_ && k == 2)
      sign = diametralSideFiltered (pts[facet[0]].point (), pts[facet[1]].point (), pts[v[i]].point ());
    if (sign != 0 ? sign < 0 : insideSmallestOrthosphere (facet, n, v[i]))
      inside |= 1u << i;
  }
  return inside;
}

} // namespace pcl_wrap::detail
