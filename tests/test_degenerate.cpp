// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Degenerate input (docs/design.md §7): ties decided by the same symbolic perturbation CGAL's
// triangulation uses, the invariants on every degenerate family, and an output that depends on
// neither the order of the points, nor the run, nor the number of threads.
#include "support/degenerate_samples.h"
#include "support/flow_checks.h"
#include "support/pipeline.h"
#include "support/wrap_checks.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <limits>
#include <random>
#include <set>
#include <thread>

namespace pcl_wrap::test
{
namespace
{

/** The triangulation CGAL built is Delaunay for the perturbed input as our predicates see it:
  * no vertex is inside the orthosphere of a top simplex. On cospherical points this holds only
  * if both break ties the same way. */
void
expectPerturbedEmptySpheres (const Pipeline& p)
{
  const int d = p.dimension ();
  for (detail::SimplexId t = 0; t < p.complex.size (d); ++t)
  {
    const std::uint32_t* v = p.complex.vertices (d, t);
    for (std::uint32_t q = 0; q < p.points.size (); ++q)
      if (std::find (v, v + d + 1, q) == v + d + 1)
        ASSERT_FALSE (p.predicates->insideSmallestOrthosphere (v, d + 1, q)) << "top simplex " << t << " vertex " << q;
  }
}

/** A side^3 grid (cospherical ties everywhere) and the points of a unit \a sphere, scaled by
  * \a radius about the grid's centre. */
std::vector<Point3>
gridAndSphere (int side, const std::vector<Point3>& sphere, double radius)
{
  auto p = gridSample (side, side, side);
  const double centre = (side - 1) / 2.0;
  for (const auto& q : sphere)
    p.push_back ({centre + radius * q[0], centre + radius * q[1], centre + radius * q[2]});
  return p;
}

TEST (Degenerate, PerturbationAgreesWithCgalTriangulation)
{
  for (const auto& [name, points] :
       std::vector<NamedSample>{{"cube corners", gridSample (2, 2, 2)},
                                {"grid", gridSample (4, 4, 4)},
                                {"integer sphere", integerSphereSample (50)},
                                {"planar grid", gridSample (6, 5, 1)},
                                {"icosahedron", regularPolyhedra ()[3]}})
  {
    SCOPED_TRACE (name);
    const Pipeline p (points);
    expectPerturbedEmptySpheres (p);
    EXPECT_GT (p.predicates->perturbations (), 0u) << "the family should have exact ties";
  }
}

/** Weights 0 and 1/4 (exact in binary) on alternate z-layers of a grid: every grid cube's 8
  * corners still share one orthogonal sphere, so the power tests still tie. */
std::vector<double>
layerWeights (const std::vector<Point3>& grid)
{
  std::vector<double> w;
  for (const auto& p : grid)
    w.push_back (int (p[2]) % 2 ? 0.25 : 0.0);
  return w;
}

TEST (Degenerate, WeightedTiesAgreeWithCgalAndKeepTheInvariants)
{
  const auto grid = gridSample (5, 5, 5);
  for (const auto& weights : {layerWeights (grid), std::vector<double> (grid.size (), 0.3)})
  {
    const Pipeline p (grid, weights);
    expectPerturbedEmptySpheres (p);
    EXPECT_GT (p.predicates->perturbations (), 0u);
    expectFlowInvariants (p);
    expectWrapInvariants (computeWrap (grid, weights, rawOutput ()));
  }
}

TEST (Degenerate, EveryFamilyKeepsTheInvariants)
{
  for (const auto& [name, points] : degenerateFamilies ())
  {
    SCOPED_TRACE (name);
    const Pipeline pipeline (points);
    expectFlowInvariants (pipeline);
    expectCofaceCounts (pipeline);
    const WrapResult r = computeWrap (points, rawOutput ());
    expectWrapInvariants (r);
    const std::size_t expected_dimension = name == "one point" ? 0 : name == "two points" || name == "collinear" ? 1
                                         : name == "three points" || name == "planar grid" ? 2 : 3;
    EXPECT_EQ (r.statistics.triangulation_dimension, int (expected_dimension));
  }
}

using Coordinates = std::vector<std::array<double, 3>>;

/** X and W as sets of sorted coordinate tuples: what the output is, whatever the indices. */
struct Geometry
{
  std::set<Coordinates> x, w_triangles, w_edges, w_vertices;
  bool operator== (const Geometry& o) const
  {
    return x == o.x && w_triangles == o.w_triangles && w_edges == o.w_edges && w_vertices == o.w_vertices;
  }
};

Geometry
geometryOf (const std::vector<Point3>& points, const WrapResult& r)
{
  const auto coordinates = [&] (auto first, auto last) {
    Coordinates c;
    for (auto it = first; it != last; ++it)
      c.push_back (points[*it]);
    std::sort (c.begin (), c.end ());
    return c;
  };
  Geometry g;
  for (const auto& t : tuplesOfX (r))
    g.x.insert (coordinates (t.begin (), t.end ()));
  for (const auto& t : r.surface.triangles)
    g.w_triangles.insert (coordinates (t.begin (), t.end ()));
  for (const auto& e : r.surface.dangling_edges)
    g.w_edges.insert (coordinates (e.begin (), e.end ()));
  for (PointIndex v : r.surface.isolated_vertices)
    g.w_vertices.insert ({points[v]});
  return g;
}

TEST (Degenerate, OutputDoesNotDependOnTheOrderOfThePoints)
{
  auto families = degenerateFamilies ();
  families.push_back ({"random cube", cubeSample (500, 8)});
  families.push_back ({"noisy sphere", sphereSample (500, 8, 0.01)});
  for (const auto& [name, points] : families)
  {
    SCOPED_TRACE (name);
    const Geometry reference = geometryOf (points, computeWrap (points, rawOutput ()));
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
      auto shuffled = points;
      std::shuffle (shuffled.begin (), shuffled.end (), std::mt19937 (seed));
      EXPECT_TRUE (geometryOf (shuffled, computeWrap (shuffled, rawOutput ())) == reference) << "shuffle " << seed;
    }
  }
}

TEST (Degenerate, OutputDoesNotChangeFromRunToRunOrWithThreads)
{
  // Over 20000 points, so that the triangulation is built by parallel insertion (when there
  // is more than one thread), on a grid full of cospherical ties.
  const auto points = gridAndSphere (28, sphereSample (3000, 5, 0.02), 13);
  WrapParameters parameters = rawOutput ();
  const WrapResult reference = computeWrap (points, parameters);
  EXPECT_GT (reference.statistics.perturbations, 0u);
  for (unsigned threads : {1u, 2u, 0u, 1u})
  {
    parameters.num_threads = threads;
    const WrapResult r = computeWrap (points, parameters);
    EXPECT_EQ (r.surface.triangles, reference.surface.triangles) << threads << " threads";
    EXPECT_EQ (r.surface.dangling_edges, reference.surface.dangling_edges);
    EXPECT_EQ (r.statistics.perturbations, reference.statistics.perturbations);
    EXPECT_EQ (r.statistics.simplices, reference.statistics.simplices);
    for (int k = 0; k <= 3; ++k)
    {
      EXPECT_EQ (r.complex[k].vertices, reference.complex[k].vertices);
      EXPECT_EQ (r.complex[k].classes, reference.complex[k].classes);
      EXPECT_EQ (r.complex[k].in_x, reference.complex[k].in_x);
    }
  }
}

TEST (Degenerate, InsertionInRoundsForProgressGivesTheSameOutput)
{
  // From 100000 points an observed triangulation inserts the points in rounds, to report how far
  // it has come: the output is that of one insertion, cospherical (and, on a plane, cocircular)
  // ties included, the triangles in the same order.
  for (const auto& [name, points] :
       std::vector<NamedSample>{{"grid and sphere", gridAndSphere (20, sphereSample (95000, 7, 0.01), 12)},
                                {"planar grid", gridSample (320, 320, 1)}})
  {
    SCOPED_TRACE (name);
    const WrapParameters parameters = rawOutput ();
    const WrapResult reference = computeWrap (points, parameters);
    std::vector<double> reported;
    const WrapResult observed = computeWrap (points, std::vector<double> (points.size (), 0.0), parameters, {},
                                             [&] (const std::string& stage, double done) {
                                               EXPECT_EQ (stage, "triangulation");
                                               reported.push_back (done);
                                             });
    ASSERT_GT (reported.size (), 1u);
    EXPECT_TRUE (std::is_sorted (reported.begin (), reported.end ()));
    EXPECT_EQ (reported.back (), 1.0);
    EXPECT_EQ (observed.statistics.triangulation_dimension, reference.statistics.triangulation_dimension);
    EXPECT_EQ (observed.statistics.perturbations, reference.statistics.perturbations);
    EXPECT_EQ (observed.statistics.simplices, reference.statistics.simplices);
    EXPECT_GT (reference.surface.triangles.size (), 0u);
    EXPECT_EQ (observed.surface.triangles, reference.surface.triangles);
    EXPECT_EQ (observed.surface.dangling_edges, reference.surface.dangling_edges);
  }
}

TEST (Degenerate, AThreadCountHoldsForItsCallOnly)
{
  // Large enough for the parallel insertion and the surface stage's concurrent flood.
  const auto points = sphereSample (30000, 3, 0.01);
  const int everywhere = tbb::this_task_arena::max_concurrency ();
  const std::size_t limit = tbb::global_control::active_value (tbb::global_control::max_allowed_parallelism);
  WrapParameters parameters;
  parameters.num_threads = 1;
  std::vector<int> during;
  const WrapResult one = computeWrap (points, parameters, [&] (const std::string&, double) {
    during.push_back (tbb::this_task_arena::max_concurrency ());
    EXPECT_EQ (tbb::global_control::active_value (tbb::global_control::max_allowed_parallelism), limit);
    int elsewhere = 0; // what another thread of the process may use meanwhile
    std::thread ([&] { elsewhere = tbb::this_task_arena::max_concurrency (); }).join ();
    EXPECT_EQ (elsewhere, everywhere);
  });
  ASSERT_FALSE (during.empty ());
  for (int c : during)
    EXPECT_EQ (c, 1);
  parameters.num_threads = 0;
  EXPECT_EQ (computeWrap (points, parameters).surface.triangles, one.surface.triangles);
}

TEST (Degenerate, HostileCoordinatesNeverCrash)
{
  const double nan = std::numeric_limits<double>::quiet_NaN ();
  const double inf = std::numeric_limits<double>::infinity ();
  const double denormal = std::numeric_limits<double>::denorm_min ();
  std::vector<Point3> points = {{nan, 0, 0}, {inf, 1, 1}, {-inf, 0, 1}, {0, nan, inf}};
  for (int i = 0; i < 6; ++i)
    points.push_back ({denormal * i, denormal * (i % 2), denormal * (i % 3)});
  for (double scale : {1e150, 1e300, 1e-300})
    for (const auto& p : cubeSample (20, 2))
      points.push_back ({scale * p[0], scale * p[1], scale * p[2]});
  for (const auto& p : gridSample (3, 3, 3))
    points.push_back ({std::numeric_limits<double>::max () * (p[0] - 1) / 2, p[1], p[2]});
  const WrapResult r = computeWrap (points, rawOutput ());
  EXPECT_EQ (r.statistics.points_skipped, 4u);
  EXPECT_EQ (r.statistics.triangulation_dimension, 3);
  expectWrapInvariants (r);
}

} // namespace
} // namespace pcl_wrap::test
