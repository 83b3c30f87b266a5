// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_reach.h"

#include "util/filled_in_parallel.h"

#include <pcl_wrap/compute_wrap.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief A tile's own points, to answer whether a tetrahedron of another tile may reach one of
  * them.
  *
  * A k-d tree of boxes answers most questions. A ball whose sphere runs along many of the points
  * (the orthosphere of points on a thin shell is nearly the shell: it meets every box of the tree,
  * though it holds no point) is answered instead by the point nearest its centre, found by a
  * greedy walk on the Delaunay graph of the points, which is built on first need: when such balls
  * are more than one per 32 points. */
class TileSearch
{
public:
  explicit TileSearch (std::vector<Point3> points);

  /** \brief Per reach, whether some point may be in it: never false when one is
    * (TileReach::mayMeet on the tree's boxes and on the points, or
    * TileReach::mayMeetBeyond on the point nearest a ball's centre). On all threads. */
  std::vector<std::uint8_t> anyMayBeIn (const std::vector<const TileReach*>& reaches);
  /** \brief How many reaches anyMayBeIn() answered by the nearest point so far. */
  std::size_t byNearest () const { return by_nearest_; }

private:
  struct Node
  {
    Box box;
    std::uint32_t begin = 0, end = 0;   ///< points_[begin, end) when a leaf
    std::uint32_t below = 0, above = 0; ///< children, 0 for a leaf
  };
  static constexpr std::uint8_t NO = 0, YES = 1, UNDECIDED = 2;

  std::uint32_t build (std::uint32_t begin, std::uint32_t end);
  /** YES or NO from the tree; UNDECIDED for a ball that meets more than \a leaf_budget leaves. */
  std::uint8_t byBoxes (const TileReach& reach, std::size_t leaf_budget) const;
  /** The point nearest \a q: from the first point of the leaf the tree descends to towards q,
    * to a nearer neighbour in the Delaunay graph while there is one, by exact comparisons (a
    * point that is not the nearest has a nearer Delaunay neighbour). */
  std::uint32_t nearest (const Point3& q) const;
  void buildDelaunayGraph ();

  static constexpr std::uint32_t LEAF_POINTS = 16;
  static constexpr std::size_t LEAF_BUDGET = 64;
  static constexpr std::size_t UNDECIDED_PER_POINT = 32; // see anyMayBeIn()
  std::vector<Point3> points_;
  std::vector<Node> nodes_;
  // The Delaunay graph, compressed: the neighbours of point i are neighbours_[first_[i], first_[i + 1]).
  std::vector<std::size_t> first_;
  detail::FilledInParallel<std::uint32_t> neighbours_;
  std::size_t by_nearest_ = 0;
};

} // namespace pcl_wrap::mpi
