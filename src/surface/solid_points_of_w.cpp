// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_points_of_w.h"

#include "surface/solid_join.h"

namespace pcl_wrap::detail
{
namespace
{

/** Rounds of moves: a point that a move brings on can open the way for a point next to it. */
constexpr int MAX_ROUNDS = 8;

enum : std::uint8_t
{
  ON_W = 1,
  HAS_INSIDE = 2,
  HAS_OUTSIDE = 4,
  ON_SURFACE = HAS_INSIDE | HAS_OUTSIDE,
  ON_A_TRIANGLE_OF_W = 8
};

/** Is \a flags (pointFlags()) a point on the surface: tetrahedra on both sides around it? */
bool
onSurface (std::uint8_t flags)
{
  return (flags & ON_SURFACE) == ON_SURFACE;
}

/** Is facet \a i of tetrahedron \a t, which X holds or not as \a t_in_x says, a triangle of W: one
  * of X with a tetrahedron not in X, or the hull, on a side? */
bool
facetOfW (const Tetrahedra& tetrahedra, const Subcomplex& x, std::uint32_t t, bool t_in_x, int i)
{
  return (!t_in_x || tetrahedra.neighbour (t, i) == OUTSIDE_HULL) && x.contains (tetrahedra.complex ().facet (3, t, i));
}

/** Per vertex: on W (a tetrahedron around it not in X, or a hull facet at it), the sides of its
  * tetrahedra (a hull facet of an inside tetrahedron counts as outside) and, if \a w_triangles is
  * asked for, on a triangle of W (not only on its dangling edges). */
std::vector<std::uint8_t>
pointFlags (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<std::uint8_t>& inside,
            bool w_triangles)
{
  // One pass in order: the tetrahedra's vertices are numbered along a space-filling curve, so the
  // flags they touch stay in cache, where threads would share their lines.
  std::vector<std::uint8_t> flags (tetrahedra.complex ().numVertices (), 0);
  for (std::uint32_t t = 0; t < tetrahedra.size (); ++t)
  {
    const bool in = inside[t] != 0, in_x = x.contains ({3, static_cast<SimplexId> (t)});
    const std::uint8_t side = in ? HAS_INSIDE : HAS_OUTSIDE;
    const std::uint8_t bits = in_x ? side : side | ON_W;
    for (int i = 0; i < 4; ++i)
    {
      flags[tetrahedra.vertex (t, i)] |= bits;
      const bool hull = tetrahedra.neighbour (t, i) == OUTSIDE_HULL;
      const bool w_triangle = w_triangles && facetOfW (tetrahedra, x, t, in_x, i);
      const std::uint8_t facet_bits =
          (hull ? (in ? ON_W | HAS_OUTSIDE : ON_W) : 0) | (w_triangle ? ON_A_TRIANGLE_OF_W : 0);
      for (int j = 1; j < 4 && facet_bits; ++j)
        flags[tetrahedra.vertex (t, (i + j) & 3)] |= facet_bits;
    }
  }
  return flags;
}

/** The points of W off the solid's surface (their tetrahedra all on one side), and how many points
  * are on the surface and off W. */
std::pair<std::vector<std::uint32_t>, std::size_t>
pointsOfWOffTheSurface (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<std::uint8_t>& inside)
{
  const std::vector<std::uint8_t> flags = pointFlags (tetrahedra, x, inside, false);
  std::vector<std::uint32_t> off;
  std::size_t on_surface_off_w = 0;
  for (std::uint32_t v = 0; v < flags.size (); ++v)
  {
    if ((flags[v] & ON_W) && !onSurface (flags[v]))
      off.push_back (v);
    on_surface_off_w += onSurface (flags[v]) && !(flags[v] & ON_W);
  }
  return {std::move (off), on_surface_off_w};
}

/** Is \a v on a triangle of W (facetOfW())? */
bool
onATriangleOfW (const Tetrahedra& tetrahedra, const Subcomplex& x, std::uint32_t v, Star& star)
{
  tetrahedra.gatherStar (v, star);
  for (std::uint32_t t : star.tetrahedra ())
  {
    const int at = tetrahedra.localIndex (t, v);
    const bool in_x = x.contains ({3, static_cast<SimplexId> (t)});
    for (int i = 0; i < 4; ++i)
      if (i != at && facetOfW (tetrahedra, x, t, in_x, i))
        return true;
  }
  return false;
}

/** The tetrahedron of \a v's star (all on one side) whose facet opposite \a v is on the surface
  * and whose longest edge is shortest, or OUTSIDE_HULL. */
std::uint32_t
bestMove (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, const SolidLabels& labels,
          std::uint32_t v, Star& star)
{
  const std::vector<std::uint8_t>& inside = labels.inside;
  tetrahedra.gatherStar (v, star);
  std::uint32_t best = OUTSIDE_HULL;
  double shortest = 0;
  for (std::uint32_t t : star.tetrahedra ())
  {
    if (!labels.oneGroup (tetrahedra.vertices (t)))
      continue; // across the gap between two groups of the sample
    const std::uint32_t u = tetrahedra.neighbour (t, tetrahedra.localIndex (t, v));
    // The facet opposite v is on the surface: across it, the other side (or the hull, outside).
    const bool across_inside = u != OUTSIDE_HULL && inside[u];
    if (across_inside == (inside[t] != 0))
      continue;
    const double longest = longestEdge (tetrahedra, positions, t);
    if (best == OUTSIDE_HULL || longest < shortest)
    {
      best = t;
      shortest = longest;
    }
  }
  return best;
}

} // namespace

PointsOfWBrought
bringPointsOfWOn (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                  SolidLabels& labels)
{
  // A move changes the side of one tetrahedron, whose other three points were on the surface
  // already: the points still off stay off, and only their stars need a second look.
  auto [off, on_surface_off_w] = pointsOfWOffTheSurface (tetrahedra, x, labels.inside);
  std::vector<std::uint32_t> moved;
  Star star;
  for (int round = 0; round < MAX_ROUNDS && !off.empty (); ++round)
  {
    const std::size_t before = moved.size ();
    std::size_t kept = 0;
    for (std::uint32_t v : off)
    {
      if (tetrahedra.tetrahedronOf (v) == NO_TETRAHEDRON || labels.isApart (v))
        continue;
      const std::uint32_t t = bestMove (tetrahedra, positions, labels, v, star);
      if (t == OUTSIDE_HULL)
        off[kept++] = v;
      else
      {
        labels.inside[t] = !labels.inside[t];
        moved.push_back (t);
      }
    }
    off.resize (kept);
    if (moved.size () == before)
      break;
  }
  // Each move brings on a point of W: the points on the surface and off W stay as they were.
  return {std::move (moved), std::move (off), on_surface_off_w};
}

bool
fewerPointsThanW (const Tetrahedra& tetrahedra, const Subcomplex& x, const SolidLabels& labels,
                  const PointsOfWBrought& brought)
{
  const std::vector<std::uint8_t>& inside = labels.inside;
  // The points on W's triangles and off the surface against those on the surface and off them.
  // First from the stars of the points left off alone, counting a point on W only by its dangling
  // edges as W's; if that says fewer, once more over all tetrahedra, exactly.
  Star star;
  std::size_t w_only = 0;
  for (std::uint32_t v : brought.left_off)
    w_only += !labels.isApart (v) && onATriangleOfW (tetrahedra, x, v, star);
  if (brought.on_surface_off_w >= w_only)
    return false;
  const std::vector<std::uint8_t> flags = pointFlags (tetrahedra, x, inside, true);
  std::size_t surface_only = 0;
  w_only = 0;
  for (std::uint32_t v = 0; v < flags.size (); ++v)
  {
    const std::uint8_t f = flags[v];
    w_only += (f & ON_A_TRIANGLE_OF_W) && !onSurface (f) && !labels.isApart (v);
    surface_only += !(f & ON_A_TRIANGLE_OF_W) && onSurface (f);
  }
  return surface_only < w_only;
}

} // namespace pcl_wrap::detail
