// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace pcl_wrap::test
{
namespace
{

/** Sides of the outside that each edge of W's triangles bounds. */
std::map<std::pair<PointIndex, PointIndex>, int>
sidesOfEdges (const WrapResult& r)
{
  const auto tet_faces = apexesOfXTriangles (r);
  std::map<std::pair<PointIndex, PointIndex>, int> sides;
  for (const auto& t : r.surface.triangles)
  {
    Tuple key (t.begin (), t.end ());
    std::sort (key.begin (), key.end ());
    const int n = tet_faces.count (key) ? 1 : 2;
    for (int i = 0; i < 3; ++i)
      sides[std::minmax (t[i], t[(i + 1) % 3])] += n;
  }
  return sides;
}

} // namespace

std::map<Tuple, PointIndex>
apexesOfXTriangles (const WrapResult& r)
{
  std::map<Tuple, PointIndex> apex;
  const auto tets = r.xSimplices (3);
  for (std::size_t s = 0; s < tets.size (); s += 4)
    for (int i = 0; i < 4; ++i)
    {
      Tuple f;
      for (int j = 0; j < 4; ++j)
        if (j != i)
          f.push_back (tets[s + j]);
      std::sort (f.begin (), f.end ());
      apex[f] = tets[s + i];
    }
  return apex;
}

std::vector<Tuple>
tuplesOfX (const WrapResult& r)
{
  std::vector<Tuple> x;
  for (int k = 0; k <= 3; ++k)
  {
    const auto flat = r.xSimplices (k);
    for (std::size_t s = 0; s < flat.size (); s += k + 1)
    {
      Tuple t (flat.begin () + s, flat.begin () + s + k + 1);
      std::sort (t.begin (), t.end ());
      x.push_back (t);
    }
  }
  std::sort (x.begin (), x.end ());
  return x;
}

// For a subcomplex of Del S in R^3, a simplex's link in X is a sphere exactly when it is not on
// the hull and its whole star in Del S is in X.
std::set<Tuple>
boundaryByLinks (const WrapResult& r)
{
  std::map<Tuple, bool> in_x;          // every Del simplex
  std::map<Tuple, std::vector<Tuple>> cofaces;
  std::map<Tuple, int> tets_of_triangle;
  for (int k = 0; k <= 3; ++k)
    for (std::size_t s = 0; s < r.complex[k].size (); ++s)
    {
      Tuple t (r.complex[k].vertices.begin () + (k + 1) * s, r.complex[k].vertices.begin () + (k + 1) * (s + 1));
      std::sort (t.begin (), t.end ());
      in_x[t] = r.complex[k].in_x[s];
      for (unsigned mask = 1; mask + 1 < (1u << t.size ()); ++mask)
      {
        Tuple f;
        for (std::size_t i = 0; i < t.size (); ++i)
          if (mask & (1u << i))
            f.push_back (t[i]);
        cofaces[f].push_back (t);
        tets_of_triangle[f] += k == 3 && f.size () == 3;
      }
    }
  std::set<Tuple> hull;
  const bool full_dimensional = !r.complex[3].vertices.empty ();
  for (const auto& [t, n] : tets_of_triangle)
    if (t.size () == 3 && n == 1)
      for (unsigned mask = 1; mask < 8; ++mask)
      {
        Tuple f;
        for (int i = 0; i < 3; ++i)
          if (mask & (1u << i))
            f.push_back (t[i]);
        hull.insert (f);
      }
  std::set<Tuple> boundary;
  for (const auto& [t, x] : in_x)
  {
    if (!x)
      continue;
    const auto& star = cofaces[t];
    const bool interior = full_dimensional && !hull.count (t) &&
                          std::all_of (star.begin (), star.end (), [&] (const Tuple& c) { return in_x.at (c); });
    if (!interior)
      boundary.insert (t);
  }
  return boundary;
}

std::set<Tuple>
closureOfW (const WrapSurface& w)
{
  std::set<Tuple> out;
  const auto add = [&] (Tuple t) {
    std::sort (t.begin (), t.end ());
    for (unsigned mask = 1; mask < (1u << t.size ()); ++mask)
    {
      Tuple f;
      for (std::size_t i = 0; i < t.size (); ++i)
        if (mask & (1u << i))
          f.push_back (t[i]);
      out.insert (f);
    }
  };
  for (const auto& t : w.triangles)
    add ({t[0], t[1], t[2]});
  for (const auto& e : w.dangling_edges)
    add ({e[0], e[1]});
  for (auto v : w.isolated_vertices)
    add ({v});
  return out;
}

std::string
openEdgeOfW (const WrapResult& r)
{
  for (const auto& [edge, count] : sidesOfEdges (r))
    if (count % 2 != 0)
      return std::to_string (edge.first) + "-" + std::to_string (edge.second);
  return "";
}

std::set<PointIndex>
pointsOnSurface (const WrapResult& r, std::size_t n)
{
  std::set<PointIndex> on;
  for (const auto& t : r.surface.triangles)
    for (PointIndex v : t)
      on.insert (v < n ? v : r.copies.at (v - n));
  return on;
}

std::size_t
pinchEdges (const WrapResult& r)
{
  std::size_t n = 0;
  for (const auto& [edge, count] : sidesOfEdges (r))
    n += count > 2;
  return n;
}

void
expectWrapInvariants (const WrapResult& r)
{
  ASSERT_TRUE (r.statistics.points_used == 0 || !r.complex[0].vertices.empty ())
      << "the invariants are about the complex: compute with keep_complex";
  const auto x = tuplesOfX (r);
  ASSERT_TRUE (closedUnderFaces (x));
  const Homology h = homology (x);
  EXPECT_EQ (h.components, 1u);
  EXPECT_EQ (h.euler, 1);
  EXPECT_EQ (h.betti1, 0u);
  EXPECT_EQ (closureOfW (r.surface), boundaryByLinks (r));
  EXPECT_EQ (openEdgeOfW (r), "") << "W is open there";
}

bool
xMeetsSegment (const WrapResult& r, const std::vector<Point3>& points, const Point3& a, const Point3& b)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto point = [&] (PointIndex i) { return K::Point_3 (points[i][0], points[i][1], points[i][2]); };
  const K::Segment_3 segment (K::Point_3 (a[0], a[1], a[2]), K::Point_3 (b[0], b[1], b[2]));
  const auto tets = r.xSimplices (3);
  for (std::size_t s = 0; s < tets.size (); s += 4)
    if (CGAL::do_intersect (segment, K::Tetrahedron_3 (point (tets[s]), point (tets[s + 1]), point (tets[s + 2]),
                                                       point (tets[s + 3]))))
      return true;
  const auto triangles = r.xSimplices (2);
  for (std::size_t s = 0; s < triangles.size (); s += 3)
    if (CGAL::do_intersect (segment, K::Triangle_3 (point (triangles[s]), point (triangles[s + 1]),
                                                    point (triangles[s + 2]))))
      return true;
  return false;
}

} // namespace pcl_wrap::test
