// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// Checks of a WrapResult against the definitions of X and W, shared by the tests.
#include "topology.h"

#include <pcl_wrap/compute_wrap.h>

#include <map>
#include <set>
#include <string>
#include <vector>

namespace pcl_wrap::test
{

/** X, from the result's complex, as sorted tuples. */
std::vector<Tuple>
tuplesOfX (const WrapResult& r);

/** Every triangle of a tetrahedron of X, with the tetrahedron's vertex opposite it (for a
  * triangle of two tetrahedra, either). */
std::map<Tuple, PointIndex>
apexesOfXTriangles (const WrapResult& r);

/** Bd X by the paper's definition (§2): X minus the simplices whose link in X is a sphere. */
std::set<Tuple>
boundaryByLinks (const WrapResult& r);

/** W's triangles, dangling edges and isolated vertices with all their faces. */
std::set<Tuple>
closureOfW (const WrapSurface& w);

/** Empty when W is closed: every edge of W's triangles bounds the outside on an even number of
  * sides, a sheet triangle (no tetrahedron of X behind it) counting on both its sides. Otherwise
  * names an open edge. */
std::string
openEdgeOfW (const WrapResult& r);

/** The edges of W's triangles on more than two sides: where W touches itself. */
std::size_t
pinchEdges (const WrapResult& r);

/** The input points on the triangles of \a r's surface, a copy counted as its point; \a n: the
  * number of input points. */
std::set<PointIndex>
pointsOnSurface (const WrapResult& r, std::size_t n);

/** Does X (a tetrahedron or a triangle of it) meet the segment from \a a to \a b? A tunnel
  * whose axis X meets is sealed. */
bool
xMeetsSegment (const WrapResult& r, const std::vector<Point3>& points, const Point3& a, const Point3& b);

/** Parameters for the paper's W as it is (Output::raw), which the invariant checks are about,
  * with the complex kept for them. */
inline WrapParameters
rawOutput ()
{
  WrapParameters p;
  p.output = Output::raw;
  p.keep_complex = true;
  return p;
}

/** The default parameters with the complex kept. */
inline WrapParameters
keepingComplex ()
{
  WrapParameters p;
  p.keep_complex = true;
  return p;
}

/** Asserts (gtest) X contractible, W = Bd X and W closed. */
void
expectWrapInvariants (const WrapResult& r);

} // namespace pcl_wrap::test
