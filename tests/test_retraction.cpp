// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The retraction (ALGORITHM.md §5): the engine against the naive rescanning retraction, order
// independence, X contractible, W = Bd X with its triangles oriented away from X.
#include "support/exact_reference.h"
#include "support/naive_retraction.h"
#include "support/pipeline.h"
#include "support/samplers.h"
#include "support/topology.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

namespace pcl_wrap::test
{
namespace
{

using detail::SimplexId;

std::vector<std::vector<Point3>>
shapes (std::size_t n, unsigned seed)
{
  return {cubeSample (n, seed), sphereSample (n, seed, 0.05), torusSample (n, seed)};
}

TEST (Retraction, EqualsNaiveRetractionOnExactClassesInAnyOrder)
{
  std::size_t collapsed_somewhere = 0;
  for (unsigned seed = 1; seed <= 5; ++seed)
    for (const auto& points : shapes (30, seed))
    {
      SCOPED_TRACE ("seed " + std::to_string (seed));
      const Pipeline p (points);
      // The reference sees only the exact rational classification, never the engine's.
      std::vector<NaiveSimplex> del;
      for (int k = 0; k <= p.dimension (); ++k)
        for (SimplexId s = 0; s < p.complex.size (k); ++s)
        {
          const std::uint32_t* v = p.complex.vertices (k, s);
          const ExactClass e = classifyExactly (p.points, p.weights, {v, v + k + 1}, p.dimension ());
          NaiveSimplex n{p.tuple ({k, s}), e.cls, {}};
          for (int i = 0; i <= k; ++i)
            if (e.lowest_successor_mask & (1u << i))
              n.lowest_successor.push_back (v[i]);
          std::sort (n.lowest_successor.begin (), n.lowest_successor.end ());
          del.push_back (std::move (n));
        }
      const auto reference = naiveRetraction (del, 1);
      for (unsigned order = 2; order <= 4; ++order)
        ASSERT_EQ (naiveRetraction (del, order), reference) << "the naive retraction depends on its order";
      for (std::uint64_t order : {0u, 1u, 7u})
        ASSERT_EQ (p.retractedX (order), reference) << "engine order " << order;
      collapsed_somewhere += reference.size () < del.size ();
    }
  EXPECT_GT (collapsed_somewhere, 0u);
}

TEST (Retraction, IndependentOfTheOrderOfCollapses)
{
  for (const auto& points : shapes (2000, 11))
  {
    const Pipeline p (points);
    const auto x = p.retractedX (0);
    for (std::uint64_t order = 1; order <= 4; ++order)
      EXPECT_EQ (p.retractedX (order), x);
  }
}

/** X from the result's complex, as sorted tuples. */
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

/** Bd X by the paper's definition (§2): X minus the simplices whose link in X is a sphere. For a
  * subcomplex of Del S in R^3 that is the simplices not on the hull whose whole star in Del S is
  * in X. */
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

/** W's simplices with all their faces. */
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

/** Every W triangle with a tetrahedron of X behind it has that tetrahedron on its negative side. */
void
expectOrientedAwayFromX (const std::vector<Point3>& points, const WrapResult& r)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto point = [&] (PointIndex i) { return K::Point_3 (points[i][0], points[i][1], points[i][2]); };
  std::map<Tuple, PointIndex> apex; // triangle of an X tetrahedron -> opposite vertex
  const auto tets = r.xSimplices (3);
  for (std::size_t s = 0; s < tets.size (); s += 4)
    for (int i = 0; i < 4; ++i)
    {
      Tuple t;
      for (int j = 0; j < 4; ++j)
        if (j != i)
          t.push_back (tets[s + j]);
      std::sort (t.begin (), t.end ());
      apex[t] = tets[s + i];
    }
  std::size_t checked = 0;
  for (const auto& t : r.surface.triangles)
  {
    Tuple key (t.begin (), t.end ());
    std::sort (key.begin (), key.end ());
    auto it = apex.find (key);
    if (it == apex.end ())
      continue; // a sheet
    EXPECT_EQ (CGAL::orientation (point (t[0]), point (t[1]), point (t[2]), point (it->second)), CGAL::NEGATIVE);
    ++checked;
  }
  EXPECT_GT (checked, 0u);
}

TEST (Retraction, XIsContractibleAndWIsItsBoundary)
{
  for (std::size_t n : {200u, 1000u, 3000u})
    for (unsigned seed = 1; seed <= 2; ++seed)
      for (const auto& points : shapes (n, seed))
      {
        SCOPED_TRACE ("n " + std::to_string (n) + " seed " + std::to_string (seed));
        const WrapResult r = computeWrap (points);
        const auto x = tuplesOfX (r);
        ASSERT_TRUE (closedUnderFaces (x));
        const Homology h = homology (x);
        EXPECT_EQ (h.components, 1u);
        EXPECT_EQ (h.euler, 1);
        EXPECT_EQ (h.betti1, 0u);
        EXPECT_EQ (closureOfW (r.surface), boundaryByLinks (r));
        for (const auto& t : r.surface.triangles)
          for (PointIndex v : t)
            ASSERT_LT (v, points.size ());
        expectOrientedAwayFromX (points, r);
      }
}

} // namespace
} // namespace pcl_wrap::test
