// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// An independent, slow, exact classification: every smallest orthosphere is constructed in
// rational arithmetic from its defining linear system, every barycentric coordinate computed,
// and attachment tested against *every* point, not only the link vertices.
#include <pcl_wrap/compute_wrap.h>

#include <CGAL/Exact_rational.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::test
{

using Rational = CGAL::Exact_rational;

struct ExactSphere
{
  std::array<Rational, 3> centre;
  Rational squared_radius;
  std::vector<Rational> lambda; // barycentric coordinates of the centre, one per vertex
};

/** The smallest sphere orthogonal to the weighted points \a vertices (1 to 4 of them). */
ExactSphere
smallestOrthosphere (const std::vector<Point3>& points, const std::vector<double>& weights,
                     const std::vector<std::uint32_t>& vertices);

/** Power distance of weighted point q from the sphere: ||q - y||^2 - w_q - r^2. */
Rational
power (const ExactSphere& sphere, const Point3& q, double w_q);

struct ExactClass
{
  SimplexClass cls;
  unsigned lowest_successor_mask = 0; // over the given vertex order; 0 unless confident
  bool degenerate = false;            // some sign was exactly zero: the reference cannot decide
};

/** The class of the simplex with \a vertices in a complex of dimension \a dimension, testing
  * attachment against all \a points. */
ExactClass
classifyExactly (const std::vector<Point3>& points, const std::vector<double>& weights,
                 const std::vector<std::uint32_t>& vertices, int dimension);

} // namespace pcl_wrap::test
