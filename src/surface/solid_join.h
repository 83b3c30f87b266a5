// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "surface/solid_labelling.h"
#include "surface/solid_parts.h"
#include "wrap/subcomplex.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief A part of the solid (or a void in it) with fewer vertices is a fragment: too few points
  * to show an object (or an inner surface) of their own. The labelling cuts such fragments off at
  * thin necks (horn tips, finger tips: 4 to 24 vertices on the development models); the smallest
  * separate object of bench/corpus.py has 300, its smallest inner shell 1,200. */
constexpr std::size_t FRAGMENT_VERTICES = 32;

/** \brief Two points closer than this many times the smaller of their spacings are on a gap the
  * sampling does not resolve: a join may close it, and no cut may open it. Parts cut apart by the
  * labelling lie within 1.1 spacings of each other; separate objects, as close as two spacings,
  * are apart. */
constexpr double UNRESOLVED_GAP = 1.5;

/** \brief Do \a a and \a b, whose spacings are \a spacing_a and \a spacing_b, lie a gap apart that
  * the sampling resolves: more than \a gap (UNRESOLVED_GAP) times the smaller spacing? */
bool
resolvedGap (const Point3& a, const Point3& b, double spacing_a, double spacing_b, double gap = UNRESOLVED_GAP);

/** \brief A neck of the solid (the last tie between two parts) is cut only where it crosses a gap
  * this many spacings wide or wider: between two small objects, not along a finger or a leg,
  * whose points are closer along it. */
constexpr double NECK_GAP = 4.0;

/** \brief How many times longer (by its longest edge) than another way to the solid a tetrahedron
  * that would bring a floating or buried point onto the surface must be to be taken for a spike:
  * one across the object, from a point in a fold to the solid beyond, is tens of times longer; in a
  * noisy layer the ways are alike. */
constexpr double SPIKE_LENGTH = 4.0;

/** \brief The longest edge of tetrahedron \a t. */
double
longestEdge (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, std::uint32_t t);

/** \brief The spacing at vertex \a v, whose star \a star holds: its shortest Delaunay edge (a lone
  * point of a coarse sample has a long one). */
double
spacingAt (const Tetrahedra& tetrahedra, const Star& star, std::uint32_t v, const std::vector<Point3>& positions);

/** \brief The spacing of the sample around vertex \a v, whose star \a star holds: the median of
  * spacingAt() over v and its neighbours in Del S. A random sample leaves some points far from
  * all others; at such a point, spacingAt() says more of the point than of the sampling there.
  * \param[in,out] known spacingAt() per vertex, NaN where not yet computed
  * \param scratch a star, for the neighbours' */
double
spacingAround (const Tetrahedra& tetrahedra, const Star& star, std::uint32_t v, const std::vector<Point3>& positions,
               std::vector<double>& known, Star& scratch);

/** \brief What joinPartsThroughX() did. */
struct SolidJoin
{
  std::vector<std::uint32_t> moved; ///< the tetrahedra moved inside, in the order they moved
  std::size_t parts = 0;            ///< the parts of the solid after the joins, at most
};

/** \brief Joins the parts of the solid that the labelling cut apart: from each part but the
  * largest, smallest first, the cheapest path (by summed margins) of outside tetrahedra of X to
  * another part moves inside. A tetrahedron of X is one of X's tetrahedra or has a triangle of X (a
  * sheet, where the retraction thinned a part of the solid to nothing). X is contractible: it ties
  * a part cut off at a neck (a horn, a leg) to the rest, but it also reaches across the gaps
  * between separate objects. So a path ends only at a part it reaches across a gap the sampling
  * does not resolve (its ends within UNRESOLVED_GAP spacings), except from a fragment of fewer than 32
  * vertices, too small to be an object of its own, which joins the first part it reaches. A
  * fragment that X ties to no part and that holds a point no other part holds (a few noisy points
  * beside the surface) joins the part nearest it through any outside tetrahedra of its group.
  * \param[in] positions per vertex
  * \param[in] parts the parts of the solid \a labels
  * \param[in,out] moved per tetrahedron, set for those it moves */
SolidJoin
joinPartsThroughX (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                   const SolidParts& parts, SolidLabels& labels, std::vector<std::uint8_t>& moved);

/** \brief Brings onto the solid the points the labelling left floating in the outside, in the
  * order of the vertex ids, each by a path of outside tetrahedra from its star to the solid.
  *
  * A point out of the mending's reach (none of its tetrahedra inside or next to an inside one), as
  * where the labelling cut through a thin, noisy part, takes the cheapest path (by summed margins)
  * of X's tetrahedra, as in joinPartsThroughX(). X holds every point, as a vertex of its
  * tetrahedra and triangles where it samples the object; a stray point that X holds by edges
  * alone (an outlier), or whose path is longer than a few hundred tetrahedra, stays where it is.
  *
  * A point whose star touches the solid is left to the mending, which moves one of those
  * tetrahedra.
  *
  * Where the solid beside the point is a fold or a crease away, either way can reach across the
  * object and draw a spike through it. So when a path of X's tetrahedra reaches the solid whose
  * longest edge is more than SPIKE_LENGTH times shorter than that way's (the cheapest path's
  * longest edge, or the shortest of the star's tetrahedra that touch the solid), the path whose
  * longest edge is shortest moves instead, if it buries no point.
  * \param[in] positions per vertex
  * \param[in,out] moved per tetrahedron, set for those it moves
  * \return the tetrahedra it moved inside, in the order it moved them */
std::vector<std::uint32_t>
bringFloatingPointsOn (const Tetrahedra& tetrahedra, const Subcomplex& x, const std::vector<Point3>& positions,
                       SolidLabels& labels, std::vector<std::uint8_t>& moved);

} // namespace pcl_wrap::detail
