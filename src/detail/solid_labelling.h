// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "filled_in_parallel.h"
#include "retraction.h"
#include "simplicial_complex.h"

#include <pcl_wrap/compute_wrap.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Which Delaunay tetrahedra are inside the sampled solid: 1 inside, 0 outside.
  *
  * Every tetrahedron has an empty sphere (its orthosphere). Where two tetrahedra share a triangle
  * their spheres meet at an angle: spheres on one side of a sampled surface overlap deeply (they
  * fill the same part of space), spheres on opposite sides barely touch (the surface passes
  * between them). The cosine of that angle is a scale-free, parameter-free vote: same side when
  * positive, opposite sides when negative, the stronger the closer to +-1. The outside (beyond the
  * convex hull) is a half-space sphere. Starting from it, tetrahedra are labelled in order of the
  * strongest undecided vote (a priority flood, as in Amenta, Choi and Kolluri's power crust), so
  * that weak, ambiguous votes are cast last, by which time their neighbourhood is decided.
  *
  * Wrap's X (\a x) breaks ties: with equal votes for both sides, a tetrahedron of X is inside.
  * When no tetrahedron at all comes out inside, the solid is the convex hull (SolidLabels::hull).
  *
  * \param[in] neighbours per tetrahedron, the tetrahedron across each facet or NO_NEIGHBOUR on the
  *            hull (Triangulation::neighbours) */
struct SolidLabels
{
  std::vector<std::uint8_t> inside; ///< per tetrahedron: 1 inside, 0 outside
  std::vector<float> margin;        ///< per tetrahedron: how much the winning vote beat the other
  bool hull = false;                ///< no vote enclosed anything: every tetrahedron is inside
};

SolidLabels
labelSolid (const SimplicialComplex& complex, const FilledInParallel<std::uint32_t>& neighbours,
            const std::vector<Point3>& positions, const std::vector<double>& weights, const Retraction& x);

/** \brief The tetrahedra flagged in \a inside and all their faces, per dimension: the subcomplex
  * whose boundary is the surface. */
std::array<std::vector<std::uint8_t>, 4>
solidSubcomplex (const SimplicialComplex& complex, const std::vector<std::uint8_t>& inside);

/** \brief The cosine of the angle at which the spheres (centre, squared radius) \a a and \a b
  * meet, given their centres' signed heights \a ha, \a hb above a common plane through which both
  * pass in the same circle of squared radius \a rho2: (rho2 + ha hb) / (|a| |b|). +1: the same
  * sphere; -1: tangent from opposite sides. */
double
sphereAngleCosine (double rho2, double ha, double hb);

} // namespace pcl_wrap::detail
