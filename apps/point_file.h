// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief A file that cannot be read or written; what() names the file and the problem. */
struct FileError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/** \brief The points of a file, with their weights when the file has them. */
struct PointFile
{
  std::vector<Point3> points;
  std::vector<double> weights; ///< empty, or one per point
  /** Where the sensor was: the VIEWPOINT of a .pcd file that is organised (a depth image, in its
    * sensor's frame) or whose viewpoint is not PCL's default 0. */
  std::optional<Point3> viewpoint;
};

/** \brief Reads the points of a file, by extension: .pcd and .ply through PCL's readers, .xyz and
  * .txt (lines "x y z", "x y z w" with a weight, or "x y z nx ny nz"; blank lines and # comments
  * skipped), .off and .obj (vertices only). Coordinates are kept in double precision; point i is
  * the i-th point (data line) of the file.
  * \param[in] weight_field for .pcd and .ply, the field holding the weights (empty: none)
  * \throws FileError when the file is unreadable, empty or malformed, the weight field is missing
  *         or not allowed for the format, or a finite point has a non-finite weight */
PointFile
readPointFile (const std::string& path, const std::string& weight_field = "");

/** \brief The points of readPointFile(), without weights. */
std::vector<Point3>
readPoints (const std::string& path);

} // namespace pcl_wrap::apps
