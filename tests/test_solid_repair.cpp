// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The repair of a labelled solid (docs/surface.md §2) on random labellings, checked vertex by
// vertex against the surface's links found by brute force, buried points that the mending's
// moves uncover brought on, the join of parts cut off the solid through X, the points left
// floating in a cut, brought back, W's last points brought on a tetrahedron at a time, webs across
// a gap cut where bars the points sample stay, and the spacing of the sample around a lone point.
#include "wrap/boundary.h"
#include "wrap/manifold_split.h"
#include "wrap/retraction.h"
#include "surface/solid_join.h"
#include "surface/solid_labelling.h"
#include "surface/solid_pinch_split.h"
#include "surface/solid_points_of_w.h"
#include "surface/solid_repair.h"
#include "surface/solid_voids.h"
#include "support/pipeline.h"
#include "support/samplers.h"
#include "support/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <set>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

using LinkEdges = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/** Per vertex, the edges opposite it in the surface triangles of the solid \a inside: the facets
  * of an inside tetrahedron whose other tetrahedron (found by scanning every tetrahedron's facet
  * ids, not through the engine's neighbours) is outside or missing (the hull). */
std::vector<LinkEdges>
surfaceLinks (const detail::SimplicialComplex& complex, const std::vector<std::uint8_t>& inside)
{
  std::map<detail::SimplexId, std::vector<detail::SimplexId>> tetrahedra_of_facet;
  for (detail::SimplexId t = 0; t < complex.size (3); ++t)
    for (int i = 0; i < 4; ++i)
      tetrahedra_of_facet[complex.facet (3, t, i).id].push_back (t);
  std::vector<LinkEdges> links (complex.numVertices ());
  for (const auto& [facet, tetrahedra] : tetrahedra_of_facet)
  {
    const std::size_t in = std::count_if (tetrahedra.begin (), tetrahedra.end (), [&] (auto t) { return inside[t]; });
    if (in != 1 || (tetrahedra.size () == 2 && inside[tetrahedra[0]] == inside[tetrahedra[1]]))
      continue;
    const std::uint32_t* v = complex.vertices (2, facet);
    for (int i = 0; i < 3; ++i)
      links[v[i]].emplace_back (v[(i + 1) % 3], v[(i + 2) % 3]);
  }
  return links;
}

/** Connected parts of the solid, across facets shared by two inside tetrahedra (brute force). */
std::size_t
solidParts (const detail::SimplicialComplex& complex, const std::vector<std::uint8_t>& inside)
{
  std::vector<std::uint32_t> parent (complex.size (3));
  std::iota (parent.begin (), parent.end (), 0u);
  const auto find = [&] (std::uint32_t a) {
    while (parent[a] != a)
      a = parent[a];
    return a;
  };
  std::map<detail::SimplexId, detail::SimplexId> first_of_facet;
  for (detail::SimplexId t = 0; t < complex.size (3); ++t)
    for (int i = 0; i < 4 && inside[t]; ++i)
    {
      const auto [at, is_new] = first_of_facet.emplace (complex.facet (3, t, i).id, t);
      if (!is_new)
        parent[find (at->second)] = find (t);
    }
  std::size_t parts = 0;
  for (detail::SimplexId t = 0; t < complex.size (3); ++t)
    parts += inside[t] && find (t) == t;
  return parts;
}

/** The surface of a repaired solid as the engine writes it: split where the repair left pinches. */
std::vector<Triangle>
repairedSurface (const detail::Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside,
                 const std::vector<std::uint32_t>& pinched)
{
  const detail::SimplicialComplex& complex = tetrahedra.complex ();
  const detail::Boundary w = detail::extractSolidBoundary (tetrahedra, inside);
  std::optional<detail::ManifoldSplit> split;
  if (!pinched.empty ())
    split = detail::splitSolidPinches (tetrahedra, inside, w, pinched);
  if (!pinched.empty () && !split)
  {
    const detail::Subcomplex solid (complex, detail::solidSubcomplex (complex, inside));
    split = detail::splitPinches (complex, solid, detail::extractBoundary (complex, solid));
  }
  const auto& triangles = split ? split->triangles : w.triangles;
  return {triangles.begin (), triangles.end ()};
}

/** The vertices off the surface of the solid \a inside (\a links empty) with a way on that the
  * repair did not take: a tetrahedron of the star, on the side it was given (\a given), next to
  * one on the other side (or, inside, to the hull's outside), whose move would put the vertex on. */
std::vector<std::uint32_t>
offTheSurfaceWithAWayOn (const detail::Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& given,
                         const std::vector<std::uint8_t>& inside, const std::vector<LinkEdges>& links)
{
  const detail::SimplicialComplex& complex = tetrahedra.complex ();
  std::vector<std::uint8_t> way_on (complex.numVertices (), 0);
  for (std::uint32_t t = 0; t < complex.size (3); ++t)
  {
    bool touches = false;
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = tetrahedra.neighbour (t, i);
      touches = touches || (u == detail::OUTSIDE_HULL ? inside[t] != 0 : inside[u] != inside[t]);
    }
    if (touches && given[t] == inside[t])
      for (int i = 0; i < 4; ++i)
        way_on[complex.vertex (3, t, i)] = 1;
  }
  std::vector<std::uint32_t> out;
  for (std::uint32_t v = 0; v < links.size (); ++v)
    if (links[v].empty () && way_on[v])
      out.push_back (v);
  return out;
}

/** The ball of radius sqrt 0.4 about the origin (or, given \a x, X's tetrahedra) with one
  * tetrahedron in \a one_in flipped at random, and random margins. */
detail::SolidLabels
flippedLabels (const Pipeline& p, const detail::Subcomplex* x, unsigned one_in, unsigned seed)
{
  std::mt19937 random (seed);
  detail::SolidLabels labels;
  for (detail::SimplexId t = 0; t < p.complex.size (3); ++t)
  {
    double r2 = 0;
    for (int c = 0; c < 3; ++c)
    {
      double centre = 0;
      for (int i = 0; i < 4; ++i)
        centre += p.points[p.complex.vertex (3, t, i)][c] / 4;
      r2 += centre * centre;
    }
    const bool in = x ? x->contains ({3, t}) : r2 < 0.4;
    labels.inside.push_back (in != (random () % one_in == 0));
    labels.margin.push_back (std::uniform_real_distribution<float> (0.0f, 2.0f) (random));
  }
  return labels;
}

/** 400 random points in a cube (odd seeds) or near a sphere (even seeds), and their X. */
struct RandomSample
{
  explicit RandomSample (unsigned seed) : p (seed % 2 ? cubeSample (400, seed) : sphereSample (400, seed, 0.05))
  {
    detail::Retraction (x, p.classification).retract ();
  }

  const Pipeline p;
  detail::Subcomplex x{p.complex};
};

TEST (SolidRepair, EveryVertexItLeavesIsOnOneFanOrReportedOnRandomLabellings)
{
  std::size_t before = 0, after = 0, moved = 0;
  for (unsigned seed = 1; seed <= 90; ++seed)
  {
    SCOPED_TRACE (seed);
    const RandomSample sample (seed);
    const Pipeline& p = sample.p;
    const detail::Subcomplex& x = sample.x;
    ASSERT_EQ (p.dimension (), 3);
    // A ball (or X's tetrahedra) with a random fifth of the tetrahedra flipped, random margins.
    detail::SolidLabels labels = flippedLabels (p, seed % 3 ? nullptr : &x, 5, seed);
    const std::vector<std::uint8_t> given = labels.inside;
    for (const auto& link : surfaceLinks (p.complex, given))
      before += !link.empty () && !isOneCycle (link);

    const detail::SolidRepair repair = detail::repairSolid (p.tetrahedra, x, p.points, labels);

    EXPECT_TRUE (std::is_sorted (repair.pinched.begin (), repair.pinched.end ()));
    EXPECT_TRUE (std::adjacent_find (repair.pinched.begin (), repair.pinched.end ()) == repair.pinched.end ());
    const std::vector<LinkEdges> links = surfaceLinks (p.complex, labels.inside);
    for (std::uint32_t v = 0; v < links.size (); ++v)
    {
      const bool reported = std::binary_search (repair.pinched.begin (), repair.pinched.end (), v);
      const bool one_fan = isOneCycle (links[v]);
      // Reported: the surface touches itself there. Not reported: one fan, or off the surface.
      if (reported)
        EXPECT_TRUE (!links[v].empty () && !one_fan) << "vertex " << v << " reported but not pinched";
      else
        EXPECT_TRUE (links[v].empty () || one_fan) << "vertex " << v << " pinched but not reported";
      after += reported;
    }
    // Each tetrahedron moves at most once, except that a join may take back one the mending moved.
    std::size_t changed = 0;
    for (std::size_t t = 0; t < given.size (); ++t)
      changed += given[t] != labels.inside[t];
    EXPECT_LE (changed, repair.flipped);
    moved += repair.flipped;
    // No void is left that no inner surface's points show, whichever move made it.
    detail::SolidLabels again = labels;
    std::vector<std::uint8_t> none (given.size (), 0);
    EXPECT_TRUE (detail::fillUnsampledVoids (p.tetrahedra, again, none).empty ()) << "a void left unfilled";

    const SurfaceReport surface = describeSurface (repairedSurface (p.tetrahedra, labels.inside, repair.pinched));
    EXPECT_TRUE (surface.closed_manifold);
    EXPECT_TRUE (surface.consistently_oriented);
  }
  // The labellings were pinched all over; the repair mended nearly all of it.
  EXPECT_GT (before, 1000u);
  EXPECT_LT (10 * after, before) << after << " of " << before;
  EXPECT_GT (moved, 1000u);
}

/** Per vertex, whether it is on the paper's W: a tetrahedron around it not in X, or a facet of
  * the hull at it (brute force, by counting each facet's tetrahedra). */
std::vector<std::uint8_t>
pointsOfW (const detail::SimplicialComplex& complex, const detail::Subcomplex& x)
{
  std::map<detail::SimplexId, int> tetrahedra_of_facet;
  for (detail::SimplexId t = 0; t < complex.size (3); ++t)
    for (int i = 0; i < 4; ++i)
      ++tetrahedra_of_facet[complex.facet (3, t, i).id];
  std::vector<std::uint8_t> on (complex.numVertices (), 0);
  for (detail::SimplexId t = 0; t < complex.size (3); ++t)
    if (!x.contains ({3, t}))
      for (int i = 0; i < 4; ++i)
        on[complex.vertex (3, t, i)] = 1;
  for (const auto& [facet, count] : tetrahedra_of_facet)
    if (count == 1)
      for (int i = 0; i < 3; ++i)
        on[complex.vertices (2, facet)[i]] = 1;
  return on;
}

/** The Euler characteristic of the surface whose vertices have the links \a links. */
long
surfaceEuler (const std::vector<LinkEdges>& links)
{
  std::set<std::array<std::uint32_t, 3>> triangles;
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  long vertices = 0;
  for (std::uint32_t v = 0; v < links.size (); ++v)
  {
    vertices += !links[v].empty ();
    for (const auto& [a, b] : links[v])
    {
      std::array<std::uint32_t, 3> t{v, a, b};
      std::sort (t.begin (), t.end ());
      triangles.insert (t);
      edges.insert ({std::min (v, a), std::max (v, a)});
    }
  }
  return vertices - long (edges.size ()) + long (triangles.size ());
}

TEST (SolidRepair, AMoveThatUncoversABuriedPointLetsTheMendingBringItOn)
{
  // The solid is the whole hull of points in a cube, so every inner point is buried, and only those
  // next to the hull have a tetrahedron of their star that touches the outside. Each move of the
  // mending makes its neighbours touch the outside, and so gives the points a tetrahedron deeper
  // a way on: none is left off the surface with a way on it did not take.
  std::size_t left = 0, on = 0;
  for (unsigned seed = 1; seed <= 20; seed += 2)
  {
    SCOPED_TRACE (seed);
    const RandomSample sample (seed);
    const Pipeline& p = sample.p;
    detail::SolidLabels labels;
    labels.inside.assign (p.complex.size (3), 1);
    labels.margin.assign (p.complex.size (3), 1.0f);
    const std::vector<std::uint8_t> given = labels.inside;

    detail::repairSolid (p.tetrahedra, sample.x, p.points, labels);

    const std::vector<LinkEdges> links = surfaceLinks (p.complex, labels.inside);
    const std::vector<std::uint32_t> stranded = offTheSurfaceWithAWayOn (p.tetrahedra, given, labels.inside, links);
    EXPECT_TRUE (stranded.empty ()) << stranded.size () << " off the surface with a way on, the first " << stranded[0];
    left += stranded.size ();
    for (const LinkEdges& link : links)
      on += !link.empty ();
  }
  std::printf ("points on the surface: %zu, off it with a way on: %zu\n", on, left);
}

TEST (SolidRepair, PointsOfWComeOnATetrahedronAtATimeAndKeepTheSurfacesTopology)
{
  std::size_t brought = 0;
  for (unsigned seed = 1; seed <= 20; ++seed)
  {
    SCOPED_TRACE (seed);
    const RandomSample sample (seed);
    const Pipeline& p = sample.p;
    const detail::Subcomplex& x = sample.x;
    ASSERT_EQ (p.dimension (), 3);
    // A ball with a random tenth of its tetrahedra flipped, repaired: a surface that leaves some of
    // W's points off it, on either side.
    detail::SolidLabels labels = flippedLabels (p, nullptr, 10, seed);
    detail::repairSolid (p.tetrahedra, x, p.points, labels);
    const std::vector<LinkEdges> before = surfaceLinks (p.complex, labels.inside);
    const std::vector<std::uint8_t> on_w = pointsOfW (p.complex, x);
    const std::size_t parts = solidParts (p.complex, labels.inside);

    const std::vector<std::uint32_t> moved = detail::bringPointsOfWOn (p.tetrahedra, x, p.points, labels).moved;

    const std::vector<LinkEdges> after = surfaceLinks (p.complex, labels.inside);
    std::size_t came_on = 0;
    for (std::uint32_t v = 0; v < before.size (); ++v)
      if (!before[v].empty ())
        EXPECT_EQ (isOneCycle (before[v]), isOneCycle (after[v])) << "vertex " << v << " changed its fans";
      else if (!after[v].empty ())
      {
        EXPECT_TRUE (on_w[v]) << "vertex " << v << " is not on W";
        EXPECT_TRUE (isOneCycle (after[v])) << "vertex " << v << " came on in more than one fan";
        ++came_on;
      }
    EXPECT_EQ (came_on, moved.size ()) << "one point per moved tetrahedron";
    EXPECT_EQ (surfaceEuler (before), surfaceEuler (after));
    EXPECT_EQ (solidParts (p.complex, labels.inside), parts);
    brought += came_on;
  }
  EXPECT_GT (brought, 10u) << "the labellings left points to bring";
  std::printf ("points of W brought on: %zu\n", brought);
}

TEST (SolidRepair, FewerPointsThanWCountsAsTheSurfaceAndWShowThem)
{
  // Labellings of X with a few tetrahedra flipped (a cube's points), or of the half of X above a
  // plane (a sphere's, half of W's points off its surface): the answer, read from the points left
  // off and one pass at most, against the points of the surface's links and of W's triangles,
  // counted by brute force.
  std::size_t fewer = 0, not_fewer = 0;
  for (unsigned seed = 1; seed <= 20; ++seed)
  {
    SCOPED_TRACE (seed);
    const RandomSample sample (seed);
    const Pipeline& p = sample.p;
    const detail::Subcomplex& x = sample.x;
    detail::SolidLabels labels = flippedLabels (p, &x, 20 + seed, seed);
    for (detail::SimplexId t = 0; t < p.complex.size (3) && seed % 2 == 0; ++t)
      labels.inside[t] = x.contains ({3, t}) && p.points[p.complex.vertex (3, t, 0)][2] > 0.3;
    const detail::PointsOfWBrought brought = detail::bringPointsOfWOn (p.tetrahedra, x, p.points, labels);

    const std::vector<LinkEdges> links = surfaceLinks (p.complex, labels.inside);
    std::set<std::uint32_t> on_surface, on_w;
    for (std::uint32_t v = 0; v < links.size (); ++v)
      if (!links[v].empty ())
        on_surface.insert (v);
    for (const auto& t : detail::extractBoundary (p.complex, x).triangles)
      on_w.insert (t.begin (), t.end ());
    const bool expected = on_surface.size () < on_w.size ();
    EXPECT_EQ (detail::fewerPointsThanW (p.tetrahedra, x, labels, brought), expected)
        << on_surface.size () << " points on the surface, " << on_w.size () << " on W's triangles";
    (expected ? fewer : not_fewer) += 1;
  }
  EXPECT_GT (fewer, 0u);
  EXPECT_GT (not_fewer, 0u);
  std::printf ("surfaces with fewer points than W: %zu of %zu\n", fewer, fewer + not_fewer);
}

/** A dense sphere's points and their X, which fills the ball. */
class CutSphereRepair : public ::testing::Test
{
protected:
  CutSphereRepair () { detail::Retraction (x, p.classification).retract (); }

  const Pipeline p{sphereSample (3000, 4, 1e-3)};
  detail::Subcomplex x{p.complex};
};

/** The tetrahedra of \a x but those of a slab around z = 0, as labels of equal margins: those whose
  * corners' \a height (the mean or the largest of their |z|) is at most \a half_width. */
template <class Height>
detail::SolidLabels
xCutBySlab (const Pipeline& p, const detail::Subcomplex& x, const Height& height, double half_width)
{
  detail::SolidLabels labels;
  for (detail::SimplexId t = 0; t < p.complex.size (3); ++t)
  {
    std::array<double, 4> z;
    for (int i = 0; i < 4; ++i)
      z[i] = std::abs (p.points[p.complex.vertex (3, t, i)][2]);
    labels.inside.push_back (x.contains ({3, t}) && height (z) > half_width);
    labels.margin.push_back (1.0f);
  }
  return labels;
}

TEST_F (CutSphereRepair, JoinsAPartCutOffTheSolidThroughX)
{
  // A slab cut out of X leaves two half balls: X, which is contractible, ties them together again.
  detail::SolidLabels labels = xCutBySlab (
      p, x, [] (const std::array<double, 4>& z) { return (z[0] + z[1] + z[2] + z[3]) / 4; }, 0.1);
  std::size_t cut = 0;
  for (detail::SimplexId t = 0; t < p.complex.size (3); ++t)
    cut += x.contains ({3, t}) && !labels.inside[t];
  ASSERT_GT (cut, 100u);
  ASSERT_GE (solidParts (p.complex, labels.inside), 2u);

  const detail::SolidRepair repair = detail::repairSolid (p.tetrahedra, x, p.points, labels);

  EXPECT_EQ (solidParts (p.complex, labels.inside), 1u);
  const SurfaceReport surface = describeSurface (repairedSurface (p.tetrahedra, labels.inside, repair.pinched));
  EXPECT_TRUE (surface.closed_manifold);
  EXPECT_EQ (surface.components, 1u);
  EXPECT_EQ (surface.euler, 2) << "a sphere";
}

TEST_F (CutSphereRepair, BringsOnThePointsLeftFloatingInACut)
{
  // The same cut, but of the labelled solid's own tetrahedra: the points of the slab float in the
  // outside, none of their tetrahedra inside. X holds them, and they come back onto the surface.
  detail::SolidLabels labels = xCutBySlab (
      p, x, [] (const std::array<double, 4>& z) { return *std::max_element (z.begin (), z.end ()); }, 0.2);
  std::vector<std::uint8_t> on_solid (p.complex.numVertices (), 0);
  for (detail::SimplexId t = 0; t < p.complex.size (3); ++t)
    for (int i = 0; i < 4 && labels.inside[t]; ++i)
      on_solid[p.complex.vertex (3, t, i)] = 1;
  const std::size_t floating = std::count (on_solid.begin (), on_solid.end (), 0);
  ASSERT_GT (floating, 200u);

  const detail::SolidRepair repair = detail::repairSolid (p.tetrahedra, x, p.points, labels);

  const std::vector<Triangle> surface_triangles = repairedSurface (p.tetrahedra, labels.inside, repair.pinched);
  std::vector<std::uint8_t> on_surface (p.complex.numVertices (), 0);
  for (const Triangle& f : surface_triangles)
    for (std::uint32_t v : f)
      if (v < on_surface.size ())
        on_surface[v] = 1;
  // The repair then cuts the handles that paths to both halves make, which takes a few off again.
  EXPECT_LT (std::count (on_surface.begin (), on_surface.end (), 0), floating / 20) << "of " << floating;
  const SurfaceReport surface = describeSurface (surface_triangles);
  EXPECT_TRUE (surface.closed_manifold);
  EXPECT_EQ (surface.components, 1u);
  EXPECT_EQ (surface.euler, 2) << "a sphere";
}

/** Where the tubes across the gap between the two balls run: at y = +-TUBE_Y, z = 0. */
constexpr double TUBE_Y = 0.35;
constexpr double GAP = 0.15; // about five spacings

/** The spheres of two balls GAP apart along x and, when \a bar_spacing > 0, a thin bar across the
  * gap along each tube, sampled by rings of six points of radius \a bar_spacing, as far apart. */
std::vector<Point3>
twoSpheresApart (double bar_spacing)
{
  std::vector<Point3> points = sphereSample (3000, 5);
  for (const Point3& q : sphereSample (3000, 6))
    points.push_back ({q[0] + 2 + GAP, q[1], q[2]});
  const double surface_x = std::sqrt (1 - TUBE_Y * TUBE_Y);
  int ring = 0;
  for (double x = surface_x; bar_spacing > 0 && x < 2 + GAP - surface_x; x += bar_spacing, ++ring)
    for (double y : {-TUBE_Y, TUBE_Y})
      for (int k = 0; k < 6; ++k)
      {
        const double angle = (k + 0.5 * (ring % 2)) * M_PI / 3;
        points.push_back ({x, y + bar_spacing * std::cos (angle), bar_spacing * std::sin (angle)});
      }
  return points;
}

/** The repaired surface of twoSpheresApart (\a bar_spacing), labelled as the labelling labels it
  * and then tied by two thin tubes across the gap, as a labelling leaves between close objects:
  * the tetrahedra whose centroids lie within 0.04 of either tube's line, between the balls, are
  * moved inside. \a points: how many points it has. */
SurfaceReport
repairedTwoBallsTiedByTubes (double bar_spacing, std::size_t& points)
{
  const Pipeline p (twoSpheresApart (bar_spacing));
  detail::Subcomplex x (p.complex);
  detail::Retraction (x, p.classification).retract ();
  detail::SolidLabelling labelling (p.complex.vertexArray (3), p.tetrahedra, p.points, p.weights);
  labelling.flood ();
  detail::SolidLabels labels = labelling.labels (x);
  for (detail::SimplexId t = 0; t < p.complex.size (3); ++t)
  {
    Point3 centroid{0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int c = 0; c < 3; ++c)
        centroid[c] += p.points[p.complex.vertex (3, t, i)][c] / 4;
    for (double y : {-TUBE_Y, TUBE_Y})
      if (centroid[0] > 0.5 && centroid[0] < 1.5 + GAP && std::hypot (centroid[1] - y, centroid[2]) < 0.04)
        labels.inside[t] = 1;
  }
  EXPECT_EQ (solidParts (p.complex, labels.inside), 1u) << "tied";
  points = p.points.size ();
  const detail::SolidRepair repair = detail::repairSolid (p.tetrahedra, x, p.points, labels);
  return describeSurface (repairedSurface (p.tetrahedra, labels.inside, repair.pinched));
}

TEST (SolidRepair, CutsWebsAcrossAGapButKeepsBarsThePointsSample)
{
  struct Case
  {
    double bar_spacing;
    std::size_t components;
    long euler;
  };
  // No point samples the tubes: a handle and a bridge of the solid across an empty gap, both cut
  // (two spheres). Or the points sample a thin bar along each tube: they show the bars, which
  // stay (one handle between the two balls).
  for (const Case& c : {Case{0, 2, 4}, Case{0.035, 1, 0}})
  {
    SCOPED_TRACE (c.bar_spacing);
    std::size_t points = 0;
    const SurfaceReport surface = repairedTwoBallsTiedByTubes (c.bar_spacing, points);
    EXPECT_TRUE (surface.closed_manifold);
    EXPECT_EQ (surface.components, c.components);
    EXPECT_EQ (surface.euler, c.euler);
    EXPECT_EQ (surface.vertices, points);
  }
}

TEST (SolidRepair, SpacingAroundALonePointIsTheSamples)
{
  // A jittered lattice of unit spacing with a hole, the points within 1.6 of its middle taken out,
  // and one point put back at the middle: its nearest neighbour is about sqrt 3 away, but the
  // sample around it is as dense as the rest.
  std::mt19937 random (11);
  std::uniform_real_distribution<double> jitter (-0.05, 0.05);
  std::vector<Point3> points;
  const Point3 middle{3.01, 2.98, 3.02};
  for (int x = 0; x < 7; ++x)
    for (int y = 0; y < 7; ++y)
      for (int z = 0; z < 7; ++z)
        if (std::hypot (x - 3, y - 3, z - 3) > 1.6)
          points.push_back ({x + jitter (random), y + jitter (random), z + jitter (random)});
  points.push_back (middle);
  const Pipeline p (points);
  std::vector<double> known (p.points.size (), std::numeric_limits<double>::quiet_NaN ());
  detail::Star star, scratch;
  const auto lone =
      static_cast<std::uint32_t> (std::find (p.points.begin (), p.points.end (), middle) - p.points.begin ());
  ASSERT_LT (lone, p.points.size ());
  p.tetrahedra.gatherStar (lone, star);
  const double own = detail::spacingAt (p.tetrahedra, star, lone, p.points);
  EXPECT_GT (own, 1.6);
  EXPECT_LT (detail::spacingAround (p.tetrahedra, star, lone, p.points, known, scratch), 1.15);
  EXPECT_EQ (known[lone], own); // kept for the next call
  // Away from the hole, the two agree.
  const auto corner = static_cast<std::uint32_t> (
      std::min_element (p.points.begin (), p.points.end (),
                        [] (const Point3& a, const Point3& b) { return a[0] + a[1] + a[2] < b[0] + b[1] + b[2]; }) -
      p.points.begin ());
  p.tetrahedra.gatherStar (corner, star);
  EXPECT_NEAR (detail::spacingAround (p.tetrahedra, star, corner, p.points, known, scratch),
               detail::spacingAt (p.tetrahedra, star, corner, p.points), 0.15);
}

} // namespace
} // namespace pcl_wrap::test
