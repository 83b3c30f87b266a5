// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Front deletion, "wrap tighter" (docs/design.md §6): sinks larger than delta go only when their
// basin reaches the surface, so tunnels open and no cavity is ever carved.
#include "support/front_checks.h"
#include "support/pipeline.h"
#include "support/samplers.h"
#include "support/topology.h"
#include "support/wrap_checks.h"

#include "wrap/front_deletion.h"
#include "wrap/wrap_filtration.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <memory>
#include <numeric>
#include <random>
#include <tuple>

namespace pcl_wrap::test
{
namespace
{

using detail::Retraction;
using detail::Subcomplex;
using detail::Simplex;
using detail::SimplexId;

struct Wrapped
{
  std::unique_ptr<Subcomplex> y;
  detail::FrontDeletion deletion;
};

Wrapped
frontWrap (const Pipeline& p, double delta, std::uint64_t order_seed = 0,
           const std::vector<std::uint8_t>& in_front = {})
{
  detail::WrapFiltration order;
  detail::orderSinks (p.complex, p.classification, p.points, p.weights, order);
  Wrapped w{std::make_unique<Subcomplex> (p.complex), {}};
  Retraction (*w.y, p.classification).retract (order_seed);
  w.deletion = detail::deleteExposedSinks (*w.y, p.classification, order, delta, in_front, order_seed);
  return w;
}

/** No cavity: every tetrahedron outside X reaches the outside through triangles outside X. */
bool
everyEmptyTetrahedronReachesOutside (const Pipeline& p, const Subcomplex& y)
{
  const SimplexId outside = static_cast<SimplexId> (p.complex.size (3));
  std::vector<SimplexId> parent (outside + 1);
  std::iota (parent.begin (), parent.end (), 0);
  const auto find = [&] (SimplexId a) {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  std::map<SimplexId, SimplexId> first_tet; // triangle -> a tetrahedron on it
  std::map<SimplexId, int> tets_on;
  for (SimplexId t = 0; t < p.complex.size (3); ++t)
    for (int i = 0; i < 4; ++i)
    {
      const Simplex f = p.complex.face (3, t, 15u & ~(1u << i));
      ++tets_on[f.id];
      if (y.contains (f))
        continue; // X separates the two sides
      auto [it, fresh] = first_tet.emplace (f.id, t);
      if (!fresh)
        parent[find (t)] = find (it->second);
    }
  for (const auto& [f, n] : tets_on)
    if (n == 1 && !y.contains ({2, f}))
      parent[find (first_tet.at (f))] = find (outside); // a hull triangle outside X opens to omega
  for (SimplexId t = 0; t < p.complex.size (3); ++t)
    if (!y.contains ({3, t}) && find (t) != find (outside))
      return false;
  return true;
}

SurfaceReport
surfaceOf (const Pipeline& p, const Subcomplex& y)
{
  const auto w = detail::extractBoundary (p.complex, y);
  return describeSurface ({w.triangles.begin (), w.triangles.end ()});
}

TEST (FrontDeletion, TorusOpensToAClosedGenusOneManifoldThroughEveryPoint)
{
  for (std::size_t n : {400u, 1000u})
    for (unsigned seed = 1; seed <= 3; ++seed)
    {
      SCOPED_TRACE ("n " + std::to_string (n) + " seed " + std::to_string (seed));
      const Pipeline p (torusSample (n, seed));
      // The hole's sinks have size about 0.6^2 = 0.36; the tube's own, about 0.4^2 and up to 0.18
      // on these sparse samples, go too when a threshold below them lets their basins reach the
      // surface. In between, only the hole opens.
      const Wrapped w = frontWrap (p, 0.2);
      const SurfaceReport s = surfaceOf (p, *w.y);
      EXPECT_TRUE (s.closed_manifold);
      EXPECT_TRUE (s.consistently_oriented);
      EXPECT_EQ (s.components, 1u);
      EXPECT_EQ (s.euler, 0); // genus 1
      EXPECT_EQ (s.vertices, n);
      EXPECT_GT (w.deletion.deleted, 0u);
      EXPECT_TRUE (everyEmptyTetrahedronReachesOutside (p, *w.y));
    }
}

/** Points on a box's surface around an inner sphere's, the box pierced by a cylindrical tunnel
  * (radius 0.3, axis x = y = 0.62): a solid with a cavity and a tunnel. */
std::vector<Point3>
boxWithCavityAndTunnel (unsigned seed)
{
  constexpr double AXIS = 0.62, RADIUS = 0.3;
  const auto inTunnel = [&] (const Point3& q) {
    return (q[0] - AXIS) * (q[0] - AXIS) + (q[1] - AXIS) * (q[1] - AXIS) < RADIUS * RADIUS;
  };
  std::vector<Point3> points;
  for (const auto& q : cubeSample (3000, seed))
  {
    // Project onto the box's surface: push the largest coordinate to +-1.
    int a = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs (q[i]) > std::abs (q[a]))
        a = i;
    Point3 r = q;
    r[a] = q[a] < 0 ? -1 : 1;
    if (!inTunnel (r))
      points.push_back (r);
  }
  for (const auto& q : sphereSample (600, seed, 1e-3))
    points.push_back ({0.5 * q[0], 0.5 * q[1], 0.5 * q[2]});
  std::mt19937_64 random (seed);
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  for (int i = 0; i < 500; ++i)
  {
    const double angle = 2 * M_PI * unit (random), z = 2 * unit (random) - 1;
    points.push_back ({AXIS + RADIUS * std::cos (angle), AXIS + RADIUS * std::sin (angle), z});
  }
  return points;
}

TEST (FrontDeletion, NeverCarvesACavityWhereGlobalDeletionDoes)
{
  const Pipeline cavity (boxWithCavityAndTunnel (2));
  const Pipeline sphere (sphereSample (4000, 3, 1e-3));
  const Pipeline torus (torusSample (1000, 1));
  for (const auto* p : {&cavity, &sphere, &torus})
    for (double delta : {0.1, 0.03, 0.01, 0.003})
    {
      SCOPED_TRACE ("delta " + std::to_string (delta));
      const Wrapped w = frontWrap (*p, delta);
      EXPECT_TRUE (everyEmptyTetrahedronReachesOutside (*p, *w.y));
    }
  // Global deletion of every sink larger than delta empties the cavity's inside and the space
  // between the surfaces alike, leaving a cavity the outside cannot reach.
  const auto f = detail::wrapFiltration (cavity.complex, cavity.classification, cavity.points, cavity.weights);
  std::array<std::vector<std::uint8_t>, 4> in_x;
  for (int k = 0; k <= 3; ++k)
    for (SimplexId s = 0; s < cavity.complex.size (k); ++s)
      in_x[k].push_back (f.inX ({k, s}, 0.05));
  EXPECT_FALSE (everyEmptyTetrahedronReachesOutside (cavity, Subcomplex (cavity.complex, in_x)));
}

TEST (FrontDeletion, NoSinkLeftAboveDeltaCouldReachTheSurface)
{
  const Pipeline torus (torusSample (3000, 5));
  const Pipeline sphere (sphereSample (3000, 6, 0.05));
  const Pipeline two (doubleTorusSample (2400, 2));
  std::size_t tried = 0;
  for (const auto* p : {&torus, &sphere, &two})
    for (double delta : {0.2, 0.05, 0.01})
    {
      SCOPED_TRACE ("delta " + std::to_string (delta));
      tried += expectFrontDeletionIsAFixpoint (*p, delta);
    }
  EXPECT_GT (tried, 50u);
}

TEST (FrontDeletion, IndependentOfTheOrderOfCollapses)
{
  const Pipeline torus (torusSample (1000, 2));
  const Pipeline two (doubleTorusSample (1200, 1));
  std::vector<std::uint8_t> left; // a region: the left tunnel of the double torus
  for (const Point3& q : two.points)
    left.push_back (Region::sphere (-1.1, 0, 0, 0.75).contains (q));
  for (const auto& [p, delta, in_front] : {std::tuple (&torus, 0.05, std::vector<std::uint8_t> ()),
                                          std::tuple (&two, 0.2, left)})
  {
    const Wrapped reference = frontWrap (*p, delta, 0, in_front);
    EXPECT_GT (reference.deletion.deleted, 0u);
    for (std::uint64_t order : {1u, 2u})
    {
      const Wrapped w = frontWrap (*p, delta, order, in_front);
      for (int k = 0; k <= 3; ++k)
        for (SimplexId s = 0; s < p->complex.size (k); ++s)
          ASSERT_EQ (w.y->contains ({k, s}), reference.y->contains ({k, s}));
    }
  }
}

/** Triangles of W (as vertex sets) whose points all satisfy \a keep. */
std::set<std::set<PointIndex>>
trianglesWhere (const WrapResult& r, const std::vector<Point3>& points, bool (*keep) (const Point3&))
{
  std::set<std::set<PointIndex>> out;
  for (const auto& t : r.surface.triangles)
    if (keep (points[t[0]]) && keep (points[t[1]]) && keep (points[t[2]]))
      out.insert ({t[0], t[1], t[2]});
  return out;
}

/** Local modification (§8): on a surface with two tunnels, front deletion from the part of W
  * around one tunnel opens that one only, and W away from it stays the basic wrap's, sealed
  * tunnel and its pinch edges included; from all of W, both open. */
TEST (FrontDeletion, ARegionOpensOnlyTheTunnelItHolds)
{
  for (unsigned seed = 1; seed <= 3; ++seed)
  {
    SCOPED_TRACE ("seed " + std::to_string (seed));
    const auto points = doubleTorusSample (2400, seed);
    const Point3 left_bottom{-1.1, 0, -0.4}, left_top{-1.1, 0, 0.4}, right_bottom{1.1, 0, -0.4},
        right_top{1.1, 0, 0.4};
    const auto expectClosedAndWhole = [&] (const WrapResult& r) {
      EXPECT_EQ (openEdgeOfW (r), "");
      EXPECT_EQ (describeSurface ({r.surface.triangles.begin (), r.surface.triangles.end ()}).components, 1u);
      // Sinks outside the region stay, principal or behind larger ones: no count to check.
    };
    const WrapResult basic = computeWrap (points, rawOutput ());

    WrapParameters parameters = rawOutput ();
    parameters.threshold = Threshold::size (0.2); // between the tubes' sinks (< 0.4^2) and the holes' (about 0.6^2)
    const WrapResult both = computeWrap (points, parameters);
    const SurfaceReport s = describeSurface ({both.surface.triangles.begin (), both.surface.triangles.end ()});
    EXPECT_TRUE (s.closed_manifold);
    EXPECT_TRUE (s.consistently_oriented);
    EXPECT_EQ (s.components, 1u);
    EXPECT_EQ (s.euler, -2) << "genus 2";
    EXPECT_EQ (s.vertices, points.size ());

    parameters.region = Region::sphere (-1.1, 0, 0, 0.75);
    const WrapResult left = computeWrap (points, parameters);
    expectClosedAndWhole (left);
    EXPECT_GT (left.statistics.sinks_deleted, 0u);
    EXPECT_FALSE (xMeetsSegment (left, points, left_bottom, left_top)) << "the chosen tunnel opened";
    EXPECT_TRUE (xMeetsSegment (left, points, right_bottom, right_top)) << "the other tunnel stays sealed";
    const auto right_side = [] (const Point3& q) { return q[0] > 0.4; };
    EXPECT_EQ (trianglesWhere (left, points, right_side), trianglesWhere (basic, points, right_side));

    parameters.region = Region::box (0.4, -0.7, -0.5, 1.8, 0.7, 0.5);
    const WrapResult right = computeWrap (points, parameters);
    expectClosedAndWhole (right);
    EXPECT_TRUE (xMeetsSegment (right, points, left_bottom, left_top));
    EXPECT_FALSE (xMeetsSegment (right, points, right_bottom, right_top));
    const auto left_side = [] (const Point3& q) { return q[0] < -0.4; };
    EXPECT_EQ (trianglesWhere (right, points, left_side), trianglesWhere (basic, points, left_side));
  }
}

/** A region away from any tunnel, or an empty one, changes nothing beyond the basic wrap's
  * surface there; a region needs front mode and a threshold. */
TEST (FrontDeletion, RegionParametersAreChecked)
{
  const auto points = doubleTorusSample (800, 1);
  WrapParameters parameters = rawOutput ();
  parameters.region = Region::sphere (0, 0, 0, 1);
  EXPECT_THROW (computeWrap (points, parameters), std::invalid_argument) << "no threshold";
  parameters.threshold = Threshold::size (0.2);
  parameters.deletion = SinkDeletion::global;
  EXPECT_THROW (computeWrap (points, parameters), std::invalid_argument) << "global mode";
  parameters.deletion = SinkDeletion::front;
  parameters.region = Region::box (1, 0, 0, 0, 1, 1);
  EXPECT_THROW (computeWrap (points, parameters), std::invalid_argument) << "corners swapped";
  parameters.region = Region::sphere (0, 0, std::nan (""), 1);
  EXPECT_THROW (computeWrap (points, parameters), std::invalid_argument) << "NaN centre";

  // A region holding no point: nothing is deleted, the basic wrap comes back.
  parameters.region = Region::sphere (10, 10, 10, 1);
  const WrapResult r = computeWrap (points, parameters);
  EXPECT_EQ (r.statistics.sinks_deleted, 0u);
  EXPECT_EQ (r.surface.triangles.size (), computeWrap (points, rawOutput ()).surface.triangles.size ());
}

} // namespace
} // namespace pcl_wrap::test
