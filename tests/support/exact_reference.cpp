// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "exact_reference.h"

#include <CGAL/number_utils.h>

#include <stdexcept>

namespace pcl_wrap::test
{
namespace
{

std::array<Rational, 3>
toRational (const Point3& p)
{
  return {Rational (p[0]), Rational (p[1]), Rational (p[2])};
}

Rational
dot (const std::array<Rational, 3>& a, const std::array<Rational, 3>& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

std::array<Rational, 3>
minus (const std::array<Rational, 3>& a, const std::array<Rational, 3>& b)
{
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

} // namespace

ExactSphere
smallestOrthosphere (const std::vector<Point3>& points, const std::vector<double>& weights,
                     const std::vector<std::uint32_t>& vertices)
{
  // y = p0 + sum_j a_j d_j with d_j = p_j - p0, and for every i:
  //   2 <d_i, y - p0> = |d_i|^2 - w_i + w_0     (equal power from p_i and p_0)
  const int k = static_cast<int> (vertices.size ()) - 1;
  const auto p0 = toRational (points[vertices[0]]);
  const Rational w0 (weights[vertices[0]]);
  std::vector<std::array<Rational, 3>> d (k);
  for (int j = 0; j < k; ++j)
    d[j] = minus (toRational (points[vertices[j + 1]]), p0);
  std::vector<std::vector<Rational>> m (k, std::vector<Rational> (k + 1));
  for (int i = 0; i < k; ++i)
  {
    for (int j = 0; j < k; ++j)
      m[i][j] = 2 * dot (d[i], d[j]);
    m[i][k] = dot (d[i], d[i]) - Rational (weights[vertices[i + 1]]) + w0;
  }
  for (int c = 0; c < k; ++c) // Gaussian elimination; the Gram matrix is regular
  {
    int pivot = c;
    while (pivot < k && CGAL::is_zero (m[pivot][c]))
      ++pivot;
    if (pivot == k)
      throw std::runtime_error ("smallestOrthosphere: degenerate simplex");
    std::swap (m[c], m[pivot]);
    for (int r = 0; r < k; ++r)
      if (r != c && !CGAL::is_zero (m[r][c]))
      {
        const Rational f = m[r][c] / m[c][c];
        for (int j = c; j <= k; ++j)
          m[r][j] -= f * m[c][j];
      }
  }
  ExactSphere s;
  s.lambda.assign (k + 1, Rational (0));
  s.lambda[0] = 1;
  std::array<Rational, 3> offset = {0, 0, 0};
  for (int j = 0; j < k; ++j)
  {
    const Rational a = m[j][k] / m[j][j];
    s.lambda[j + 1] = a;
    s.lambda[0] -= a;
    for (int c = 0; c < 3; ++c)
      offset[c] += a * d[j][c];
  }
  for (int c = 0; c < 3; ++c)
    s.centre[c] = p0[c] + offset[c];
  s.squared_radius = dot (offset, offset) - w0;
  return s;
}

Rational
power (const ExactSphere& sphere, const Point3& q, double w_q)
{
  const auto v = minus (toRational (q), sphere.centre);
  return dot (v, v) - Rational (w_q) - sphere.squared_radius;
}

ExactClass
classifyExactly (const std::vector<Point3>& points, const std::vector<double>& weights,
                 const std::vector<std::uint32_t>& vertices, int dimension)
{
  const ExactSphere s = smallestOrthosphere (points, weights, vertices);
  ExactClass out;
  const int k = static_cast<int> (vertices.size ()) - 1;
  if (k < dimension)
    for (std::uint32_t q = 0; q < points.size (); ++q)
    {
      if (std::find (vertices.begin (), vertices.end (), q) != vertices.end ())
        continue;
      const Rational pw = power (s, points[q], weights[q]);
      out.degenerate |= CGAL::is_zero (pw);
      if (CGAL::is_negative (pw))
      {
        out.cls = SimplexClass::equivocal;
        return out;
      }
    }
  unsigned positive = 0;
  for (int i = 0; i <= k; ++i)
  {
    out.degenerate |= k > 0 && CGAL::is_zero (s.lambda[i]);
    if (CGAL::is_positive (s.lambda[i]))
      positive |= 1u << i;
  }
  if (positive == (1u << (k + 1)) - 1)
    out.cls = SimplexClass::centered;
  else
  {
    out.cls = SimplexClass::confident;
    out.lowest_successor_mask = positive;
  }
  return out;
}

} // namespace pcl_wrap::test
