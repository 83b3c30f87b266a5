// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"
#include "util/union_find.h"

#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The connected parts of a solid, through the facets its tetrahedra share. */
struct SolidParts
{
  static constexpr std::uint32_t NO_PART = ~std::uint32_t (0);
  /** \brief Per tetrahedron, its part (NO_PART outside), numbered in the order of their lowest
    * tetrahedra. */
  std::vector<std::uint32_t> part;
  std::vector<std::uint32_t> size; ///< per part, its tetrahedra
};

/** \brief The connected parts of both sides of a labelling at once: the solid's parts and the
  * outside's (the outside proper and the voids), through the facets of tetrahedra on the same
  * side. Each part is named by its lowest tetrahedron, whatever the number of threads. */
class SideParts
{
public:
  /** \brief Which sides' parts to find. */
  enum class Sides
  {
    outside,
    solid,
    both
  };

  /** \brief The parts of the tetrahedra flagged in \a inside (the solid) and of the others (the
    * outside), or of one of the two, on all threads; the other side's tetrahedra stay apart. */
  SideParts (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside, Sides sides = Sides::both);

  /** \brief The lowest tetrahedron of \a t's part; safe on several threads at once. */
  std::uint32_t part (std::uint32_t t) { return sets_.findConcurrently (t); }

  /** \brief After whole parts of the outside, the tetrahedra \a moved, moved inside: joins them to
    * the parts of the solid around them. */
  void movedInside (const std::vector<std::uint32_t>& moved);

  /** \brief The parts of the solid \a inside (the labels these parts are of, with the solid's
    * parts found), numbered. */
  SolidParts solid (const std::vector<std::uint8_t>& inside);

private:
  const Tetrahedra& tetrahedra_;
  UnionFind sets_;
};

/** \brief The parts of the solid \a inside, on all threads; they do not depend on the number of
  * threads. */
SolidParts
solidParts (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside);

/** \brief Is the solid \a after one part, given that it was one part before the tetrahedra
  * \a changed (ascending) changed side? Judged near the change alone: yes when each connected
  * cluster of changed tetrahedra has an unchanged inside tetrahedron next to it, and the inside
  * tetrahedra in or next to the cluster are connected through at most LOCAL_REACH inside
  * tetrahedra; then every path of the solid before through the cluster has a way round it. No
  * when that does not hold, though the solid may still be one part. */
bool
staysOnePart (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& after,
              const std::vector<std::uint32_t>& changed);

} // namespace pcl_wrap::detail
