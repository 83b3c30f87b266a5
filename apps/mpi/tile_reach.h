// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <array>

namespace pcl_wrap::mpi
{

/** \brief A closed axis-aligned box: the bounding box of one tile's points. */
struct Box
{
  Point3 lo{0, 0, 0}, hi{0, 0, 0};
  bool empty = true;

  void add (const Point3& p);
  /** \brief 0, 1 or 2: the axis of the box's longest side (the first of equal ones). */
  int longestAxis () const;
  /** \brief The squared distance from \a p to the box, in floating point (to choose where to look
    * first, never to decide). */
  double distance2 (const Point3& p) const;
};

/** \brief Where a tetrahedron of a tile's triangulation reaches: the closed ball of its orthosphere,
  * its radius widened to sqrt (r^2 + w_max) so that it holds every point (of weight at most
  * w_max) that could be closer to the centre than orthogonal; a hull facet's reach is the closed
  * half-space beyond it. mayMeet() never misses a box the reach meets: the centre and radius are
  * bounded in interval arithmetic, the half-space by exact orientations of the box corners. It
  * may say yes for a box the reach only comes near, which costs points sent, never correctness. */
class TileReach
{
public:
  /** \brief The ball of the positively oriented tetrahedron \a p with weights \a w. */
  static TileReach ofTetrahedron (const std::array<Point3, 4>& p, const std::array<double, 4>& w, double w_max);
  /** \brief The half-space beyond the hull facet \a p, on the side away from \a inner. */
  static TileReach ofHullFacet (const std::array<Point3, 3>& p, const Point3& inner);

  bool mayMeet (const Box& box) const;

  /** \brief A ball (not a half-space, nor everywhere). */
  bool isBall () const { return !half_space_ && !everywhere_; }
  /** \brief A ball's centre, as near as doubles hold it (in its bounds). */
  Point3 centre () const;
  /** \brief Whether a ball may hold a point no nearer to \a q, its centre(), than \a nearest is: with
    * \a nearest the nearest point to q of a set, whether it may hold one of the set. */
  bool mayMeetBeyond (const Point3& q, const Point3& nearest) const;

private:
  bool half_space_ = false;
  bool everywhere_ = false;                         // the tetrahedron too flat to bound its ball
  std::array<double, 3> centre_lo_{}, centre_hi_{}; // the centre, bounded
  double radius2_hi_ = 0;                           // r^2 + w_max, bounded above
  std::array<Point3, 3> facet_{};
  Point3 inner_{};
};

} // namespace pcl_wrap::mpi
