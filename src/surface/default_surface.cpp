// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/default_surface.h"

#include "surface/open_sheet.h"
#include "surface/points_apart.h"
#include "surface/single_layer.h"
#include "surface/solid_pinch_split.h"
#include "surface/solid_points_of_w.h"
#include "surface/solid_repair.h"
#include "util/parallel_for_each.h"
#include "util/portable.h"

#include <algorithm>
#include <memory>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

/** Per vertex, 1 where it is on the surface of the tetrahedra flagged in \a inside; found on all
  * threads. */
std::vector<std::uint8_t>
onSolidSurface (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside)
{
  std::vector<std::uint8_t> on (tetrahedra.complex ().numVertices (), 0);
  parallelForEach (inside.size (), [&] (std::size_t t) {
    const auto id = static_cast<std::uint32_t> (t);
    for (int i = 0; inside[t] && i < 4; ++i)
    {
      const std::uint32_t u = tetrahedra.neighbour (id, i);
      if (u == OUTSIDE_HULL || !inside[u])
        for (int j = 1; j < 4; ++j)
          relaxedStore (&on[tetrahedra.vertex (id, (i + j) & 3)], std::uint8_t (1));
    }
  });
  return on;
}

/** Puts X's tetrahedra inside, and the others outside, within each group of more than
  * APART_CLUSTER points (\a groups) whose points are less than half on the surface of the
  * tetrahedra flagged in \a inside (\a on_surface: onSolidSurface()). */
void
takeXInGroupsLeftOff (const Tetrahedra& tetrahedra, const Subcomplex& x, const SampleGroups& groups,
                      const std::vector<std::uint8_t>& on_surface, std::vector<std::uint8_t>& inside)
{
  const std::vector<std::uint32_t>& group = groups.group;
  std::vector<std::uint32_t> on (group.size (), 0);
  for (std::uint32_t v = 0; v < group.size (); ++v)
    on[group[v]] += on_surface[v];
  const auto left_off = [&] (std::uint32_t g) { return groups.size[g] > APART_CLUSTER && 2 * on[g] < groups.size[g]; };
  if (std::none_of (group.begin (), group.end (), [&] (std::uint32_t g) { return left_off (g); }))
    return;
  parallelForEach (inside.size (), [&] (std::size_t t) {
    const std::uint32_t* v = tetrahedra.vertices (static_cast<std::uint32_t> (t));
    const std::uint32_t g = group[v[0]];
    if (group[v[1]] == g && group[v[2]] == g && group[v[3]] == g && left_off (g))
      inside[t] = x.contains ({3, static_cast<SimplexId> (t)});
  });
}

/** The points flagged in \a apart (per vertex, or empty: pointsApart()) that \a surface leaves off. */
std::vector<std::uint32_t>
offTheSurface (const std::vector<std::uint8_t>& apart, const Boundary& surface)
{
  std::vector<std::uint32_t> off;
  if (apart.empty ())
    return off;
  std::vector<std::uint8_t> on (apart.size (), 0);
  for (const auto& t : surface.triangles)
    for (std::uint32_t v : t)
      on[v] = 1;
  for (std::uint32_t v = 0; v < apart.size (); ++v)
    if (apart[v] && !on[v])
      off.push_back (v);
  return off;
}

/** Where X has no tetrahedron and each of its triangles has a point apart (\a apart: pointsApart())
  * among its corners, a curve with outliers beside it that X ties by triangles: the curve, the
  * paper's W less its simplices at those points (the triangles' other edges become edges of the
  * curve). Otherwise nothing. */
std::optional<Boundary>
curveLessPointsApart (const SimplicialComplex& complex, const Subcomplex& x, const std::vector<std::uint8_t>& apart)
{
  if (x.size (3) > 0 || x.size (2) == 0 || apart.empty ())
    return std::nullopt;
  for (SimplexId t = 0; t < complex.size (2); ++t)
  {
    const std::uint32_t* v = complex.vertices (2, t);
    if (x.contains ({2, t}) && !apart[v[0]] && !apart[v[1]] && !apart[v[2]])
      return std::nullopt;
  }
  const Boundary w = extractBoundary (complex, x);
  Boundary curve;
  const auto keep = [&] (std::uint32_t a, std::uint32_t b) {
    if (!apart[a] && !apart[b])
      curve.dangling_edges.push_back ({std::min (a, b), std::max (a, b)});
  };
  for (const auto& t : w.triangles)
    for (int k = 0; k < 3; ++k)
      keep (t[k], t[(k + 1) % 3]);
  for (const auto& e : w.dangling_edges)
    keep (e[0], e[1]);
  std::sort (curve.dangling_edges.begin (), curve.dangling_edges.end ());
  curve.dangling_edges.erase (std::unique (curve.dangling_edges.begin (), curve.dangling_edges.end ()),
                              curve.dangling_edges.end ());
  for (std::uint32_t v : w.isolated_vertices)
    if (!apart[v])
      curve.isolated_vertices.push_back (v);
  return curve;
}

} // namespace

DefaultSurface::DefaultSurface (const FilledInParallel<std::uint32_t>& tetrahedra, const Tetrahedra& adjacency,
                                const std::vector<Point3>& positions, const std::vector<double>& weights,
                                bool label_now)
  : adjacency_ (adjacency), positions_ (positions), weights_ (weights)
{
  if (!label_now)
    return;
  // The flood reads nothing but the votes and the neighbours, so it runs on one thread while the
  // others build the complex and compute X, which it needs only to break exact ties.
  labelling_.emplace (tetrahedra, adjacency, positions, weights);
  flooding_.run ([this] { labelling_->flood (); });
}

DefaultSurface::~DefaultSurface ()
{
  if (!labelling_)
    return;
  try
  {
    flooding_.wait ();
  }
  catch (...)
  {
  }
}

SolidLabels
DefaultSurface::labelsFor (const Subcomplex& x)
{
  if (labelling_)
    flooding_.wait ();
  else
  {
    labelling_.emplace (adjacency_.complex ().vertexArray (3), adjacency_, positions_, weights_);
    labelling_->flood ();
  }
  SolidLabels labels = labelling_->labels (x);
  labelling_.reset ();
  return labels;
}

DefaultSurface::Output
DefaultSurface::surface (const Subcomplex& x, const std::vector<Point3>& positions, bool closed,
                         const std::optional<Point3>& viewpoint, const SampleIsSingleLayer& sample_is_single_layer,
                         const InputKey& input_key, WrapStatistics& stats, StageClock& clock)
{
  const SimplicialComplex& complex = adjacency_.complex ();
  SampleGroups groups = sampleGroups (complex, positions);
  std::vector<std::uint8_t> apart = pointsApart (complex, positions, groups);
  if (std::optional<Boundary> curve = curveLessPointsApart (complex, x, apart))
  {
    // Nearly collinear points with an outlier: a curve, as where X has no triangle (below).
    Output out;
    out.w = std::move (*curve);
    out.apart = offTheSurface (apart, out.w);
    return out;
  }
  std::optional<SolidLabels> known;
  const LayerTriangles layer = layerTriangles (complex, x);
  bool single_layer = layer.singleLayer ();
  // A layer with noise across it: X is a sheet torn by thin solids, which a coarser sample does
  // not resolve. The sheet may then pass through those solids too.
  bool noisy = false;
  const std::size_t stride = noisyLayerStride (complex.numVertices ());
  if (!single_layer && stride > 0 && layer.partlySheet ())
  {
    single_layer = noisy = sample_is_single_layer (stride);
    clock.stageDone ("layer sample");
  }
  if (single_layer && complex.numVertices () < LABEL_ON_DEMAND_FROM)
  {
    known = labelsFor (x);
    single_layer = !known->hull;
  }
  if (single_layer && !closed && x.size (2) > 0)
  {
    // One open sheet through the points (a curve, with no triangle in X, is W below). The labels
    // only turn a sheet with no up or down, if there is one.
    stats.single_layer = true;
    Output out;
    Boundary candidates = extractBoundary (complex, x, false);
    if (noisy)
      addInnerTriangles (complex, x, candidates);
    out.w = openSheet (
        adjacency_, std::move (candidates), positions, [&] { return known ? known->inside : labelsFor (x).inside; },
        viewpoint, noisy);
    out.apart = offTheSurface (apart, out.w); // the sheet's gaps leave them off
    clock.stageDone ("sheet");
    return out;
  }
  if (single_layer && noisy && closed)
  {
    // The labelled solid of a noisy layer is the solid in pieces, with handles, that the sample
    // told apart: the two-sided shell alone is asked.
    stats.single_layer = true;
    TwoSidedShell shell = twoSidedShell (adjacency_, positions, x);
    stats.bridge_simplices = shell.bridges;
    clock.stageDone ("shell");
    return {std::move (shell.w), std::move (shell.split)};
  }
  SolidLabels labels = known ? std::move (*known) : labelsFor (x);
  clock.stageDone ("labelling");
  // Points that sample a volume (a grid, a thick noisy shell) lie mostly inside the solid, where
  // the votes between their small spheres say nothing; where no vote encloses anything (a few
  // scattered points), the labels' solid is the convex hull, with points inside it. Either way the
  // solid is X, whose boundary is the volume's outer surface (the paper's W), and the points
  // inside stay inside.
  const bool solid_may_be_x = !single_layer && x.size (3) > 0;
  std::vector<std::uint8_t> on_surface;
  if (solid_may_be_x && !labels.hull)
    on_surface = onSolidSurface (adjacency_, labels.inside);
  const bool volume =
      solid_may_be_x && (labels.hull || 2 * std::size_t (std::count (on_surface.begin (), on_surface.end (), 1)) <
                                            complex.numVertices ());
  if (volume)
    parallelForEach (labels.inside.size (), [&] (std::size_t t) {
      labels.inside[t] = x.contains ({3, static_cast<SimplexId> (t)});
    });
  // So is a group of points far from the rest whose points the labels leave mostly off the
  // surface: a blob of points (a volume, no vote encloses anything there) beside an object. The
  // repair brings them on.
  else if (solid_may_be_x && groups.count > 1)
    takeXInGroupsLeftOff (adjacency_, x, groups, on_surface, labels.inside);
  // A point apart from all others (an outlier) is on no surface the points show, and a closed
  // surface through it would be a spike: its tetrahedra are outside, and the repair leaves it off.
  if (x.size (3) > 0 && !apart.empty ())
  {
    labels.apart = std::move (apart);
    parallelForEach (labels.inside.size (), [&] (std::size_t t) {
      for (int i = 0; i < 4; ++i)
        if (labels.apart[adjacency_.vertex (static_cast<std::uint32_t> (t), i)])
          labels.inside[t] = 0;
    });
  }
  // The moves that bring a point on stay within its group: a tetrahedron across the gap between
  // two groups would be a spike.
  if (groups.count > 1)
    labels.group = std::move (groups.group);
  SolidRepair repair = repairSolid (adjacency_, x, positions, labels, volume);
  stats.tetrahedra_moved = repair.flipped;
  // What the repair left of W's points off the surface, a tetrahedron away. (A single layer's
  // solid that leaves points off is the sign that X's layer is the surface: below.)
  PointsOfWBrought brought = single_layer ? PointsOfWBrought{} : bringPointsOfWOn (adjacency_, x, positions, labels);
  if (!brought.left_off.empty () && fewerPointsThanW (adjacency_, x, labels, brought))
  {
    // The mending can leave a point floating where its way on, a tetrahedron next to the solid,
    // was taken from it by a neighbour's move: once more from these labels, the repair brings
    // it on as it does the labelling's floating points, through X or its group's tetrahedra.
    stats.tetrahedra_moved += brought.moved.size ();
    repair = repairSolid (adjacency_, x, positions, labels, volume);
    stats.tetrahedra_moved += repair.flipped;
    brought = bringPointsOfWOn (adjacency_, x, positions, labels);
  }
  if (!brought.moved.empty ())
  {
    stats.tetrahedra_moved += brought.moved.size ();
    repair.surface.reset ();
  }
  clock.stageDone ("repair");
  if (!brought.left_off.empty () && fewerPointsThanW (adjacency_, x, labels, brought))
  {
    // The solid's surface would hold fewer points than the paper's W (a coarse sample, where the
    // labels seal a hole that W keeps open and bury its points): the output is W, split where it
    // touches itself as the raw output's manifold split does, so that no point of W is lost.
    stats.surface_is_w = true;
    Output out;
    out.w = extractBoundary (complex, x, true, input_key);
    out.split = splitPinches (complex, x, out.w);
    out.apart = offTheSurface (labels.apart, out.w); // W holds a far outlier by an edge alone
    return out;
  }

  // The boundary of the labelled solid, repaired to a manifold; where the repair leaves it
  // touching itself, split there, at the pinched vertices alone or, when an edge needs more than
  // the two simple pairings, as the raw output's pinches are split.
  Output out;
  out.w = repair.surface ? std::move (*repair.surface) : extractSolidBoundary (adjacency_, labels.inside);
  std::unique_ptr<Subcomplex> pinched_solid;
  if (!repair.pinched.empty ())
  {
    out.split = splitSolidPinches (adjacency_, labels.inside, out.w, repair.pinched);
    if (!out.split)
    {
      pinched_solid = std::make_unique<Subcomplex> (complex, solidSubcomplex (complex, labels.inside));
      out.w = extractBoundary (complex, *pinched_solid);
    }
  }
  // The points on the solid's surface, as its boundary before any split has them.
  const bool x_is_a_curve = x.size (2) == 0;
  const std::size_t on_solid = single_layer || x_is_a_curve ? verticesOn (out.w.triangles) : 0;
  if (single_layer && on_solid < complex.numVertices ())
  {
    // The labelled solid is not Wrap's and leaves points off its surface: the points are one
    // layer, and X is that layer.
    TwoSidedShell shell = twoSidedShell (adjacency_, positions, x);
    if (verticesOn (shell.w.triangles) > on_solid)
    {
      stats.single_layer = true;
      stats.bridge_simplices = shell.bridges;
      return {std::move (shell.w), std::move (shell.split)};
    }
  }
  if (x_is_a_curve && on_solid < complex.numVertices ())
  {
    // X has no triangle: the paper's W is a curve through every point (nearly collinear points,
    // a wire). A solid that leaves points off its surface is slivers around that curve; the
    // output is W itself.
    return {extractBoundary (complex, x), std::nullopt};
  }
  if (pinched_solid)
    out.split = splitPinches (complex, *pinched_solid, out.w);
  out.apart = offTheSurface (labels.apart, out.w); // a move at a neighbour may have taken one on
  return out;
}

} // namespace pcl_wrap::detail
