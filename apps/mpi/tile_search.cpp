// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_search.h"

#include "delaunay/cgal_kernel.h"
#include "delaunay/regular_triangulation.h"
#include "util/parallel_for_each.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace pcl_wrap::mpi
{

TileSearch::TileSearch (std::vector<Point3> points) : points_ (std::move (points))
{
  if (!points_.empty ())
    build (0, static_cast<std::uint32_t> (points_.size ()));
}

std::uint32_t
TileSearch::build (std::uint32_t begin, std::uint32_t end)
{
  const auto at = static_cast<std::uint32_t> (nodes_.size ());
  nodes_.emplace_back ();
  Box box;
  for (std::uint32_t i = begin; i < end; ++i)
    box.add (points_[i]);
  nodes_[at].box = box;
  if (end - begin <= LEAF_POINTS)
  {
    nodes_[at].begin = begin;
    nodes_[at].end = end;
    return at;
  }
  const int axis = box.longestAxis ();
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element (points_.begin () + begin, points_.begin () + middle, points_.begin () + end,
                    [axis] (const Point3& a, const Point3& b) { return a[axis] < b[axis]; });
  const std::uint32_t below = build (begin, middle);
  const std::uint32_t above = build (middle, end);
  nodes_[at].below = below;
  nodes_[at].above = above;
  return at;
}

std::uint8_t
TileSearch::byBoxes (const TileReach& reach, std::size_t leaf_budget) const
{
  std::vector<std::uint32_t> stack{0};
  std::size_t leaves = 0;
  while (!stack.empty ())
  {
    const Node& node = nodes_[stack.back ()];
    stack.pop_back ();
    if (!reach.mayMeet (node.box))
      continue;
    if (node.below == 0)
    {
      if (++leaves > leaf_budget && reach.isBall ())
        return UNDECIDED;
      for (std::uint32_t i = node.begin; i < node.end; ++i)
      {
        Box point;
        point.add (points_[i]);
        if (reach.mayMeet (point))
          return YES;
      }
      continue;
    }
    stack.push_back (node.below);
    stack.push_back (node.above);
  }
  return NO;
}

std::vector<std::uint8_t>
TileSearch::anyMayBeIn (const std::vector<const TileReach*>& reaches)
{
  std::vector<std::uint8_t> answer (reaches.size (), NO);
  if (nodes_.empty ())
    return answer;
  tbb::parallel_for (std::size_t (0), reaches.size (),
                     [&] (std::size_t i) { answer[i] = byBoxes (*reaches[i], LEAF_BUDGET); });
  const auto undecided = static_cast<std::size_t> (std::count (answer.begin (), answer.end (), UNDECIDED));
  if (undecided == 0)
    return answer;
  // The walk needs the Delaunay graph, a triangulation of the points: it pays when many balls
  // hug the points (one per 32 points or more), not for a few.
  const bool walk = !first_.empty () || undecided * UNDECIDED_PER_POINT > points_.size ();
  if (walk && first_.empty ())
    buildDelaunayGraph ();
  if (walk)
    by_nearest_ += undecided;
  tbb::parallel_for (std::size_t (0), reaches.size (), [&] (std::size_t i) {
    if (answer[i] != UNDECIDED)
      return;
    const Point3 q = reaches[i]->centre ();
    answer[i] = !walk ? byBoxes (*reaches[i], std::numeric_limits<std::size_t>::max ())
                : reaches[i]->mayMeetBeyond (q, points_[nearest (q)]) ? YES
                                                                      : NO;
  });
  return answer;
}

std::uint32_t
TileSearch::nearest (const Point3& q) const
{
  std::uint32_t at = 0;
  while (nodes_[at].below != 0)
  {
    const Node &below = nodes_[nodes_[at].below], &above = nodes_[nodes_[at].above];
    at = below.box.distance2 (q) <= above.box.distance2 (q) ? nodes_[at].below : nodes_[at].above;
  }
  const detail::BarePoint target (q[0], q[1], q[2]);
  const auto bare = [&] (std::uint32_t i) { return detail::BarePoint (points_[i][0], points_[i][1], points_[i][2]); };
  std::uint32_t best = nodes_[at].begin;
  for (bool moved = true; moved;)
  {
    moved = false;
    for (std::size_t k = first_[best]; k < first_[best + 1] && !moved; ++k)
      if (CGAL::compare_distance_to_point (target, bare (neighbours_[k]), bare (best)) == CGAL::SMALLER)
      {
        best = neighbours_[k];
        moved = true;
      }
  }
  return best;
}

void
TileSearch::buildDelaunayGraph ()
{
  std::vector<std::array<std::uint32_t, 2>> edges;
  {
    detail::GrowingTriangulation delaunay (true);
    delaunay.insert (points_, std::vector<double> (points_.size (), 0.0), 0);
    edges = delaunay.edges ();
  } // freed before the graph takes its memory
  // Each edge in the lists of both its points, each list ascending, so that the walk, and so the
  // answers, do not depend on CGAL's order.
  neighbours_ = detail::bucketInParallel<std::uint32_t> (
      edges.size (), points_.size (),
      [&] (std::size_t e, auto put) {
        put (edges[e][0], edges[e][1]);
        put (edges[e][1], edges[e][0]);
      },
      first_, [] (std::size_t, auto first, auto last) { std::sort (first, last); });
}

} // namespace pcl_wrap::mpi
