// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The surface reconstructions a user would pick instead of pcl_wrap, each run as its authors'
// documentation shows, plus CGAL's triangulations alone (the floor). One function per method.
#include <pcl_wrap/compute_wrap.h>

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pcl_wrap::bench
{

/** What a method produced: a triangle mesh (its vertices need not be the input points), and the
  * seconds spent estimating normals, when it needs them (included in the total). */
struct PeerOutput
{
  std::vector<Point3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  double normal_seconds = 0.0;
  std::string note; ///< the parameters used
  std::vector<std::pair<std::string, double>> stages; ///< pcl_wrap's stage times (seconds), in order
};

using Peer = std::function<PeerOutput (const std::vector<Point3>&)>;

/** Every method by name: floor_delaunay, floor_regular, pcl_wrap, pcl_wrap_front,
  * cgal_advancing_front,
  * cgal_alpha_wrap, cgal_alpha_shape, pcl_concave_hull, pcl_greedy_projection. */
const std::vector<std::pair<std::string, Peer>>&
peers ();

/** \brief CGAL's Alpha_wrap_3 at the alpha and offset a method name gives:
  * cgal_alpha_wrap:diag/D:alpha/R (alpha = bounding box diagonal / D) or
  * cgal_alpha_wrap:spacing*S:alpha/R (alpha = S x the median spacing), offset = alpha / R;
  * nothing for any other name. */
std::optional<Peer>
alphaWrapAt (const std::string& method);

/** The median distance from a point to its nearest neighbour, through PCL's k-d tree as a user
  * of these methods would compute it: the scale the peers' parameters are set from, inside
  * their timing. */
double
medianSpacing (const std::vector<Point3>& points);

} // namespace pcl_wrap::bench
