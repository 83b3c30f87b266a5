// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "point_attributes.h"

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

/** \brief The points of a file, with their weights when asked for, and whatever else it carries. */
struct PointFile
{
  std::vector<Point3> points;
  std::vector<double> weights; ///< empty, or one per point
  PointAttributes attributes;  ///< colours, normals and other fields, to be kept on the output
  /** Where the sensor was: the VIEWPOINT of a .pcd file that is organised (a depth image, in its
    * sensor's frame) or whose viewpoint is not PCL's default 0. */
  std::optional<Point3> viewpoint;
};

/** \brief Reads the points of a file, by extension:
  * - .pcd and .ply as PCL's readers read them, every field kept (PointAttributes): the data of
  *   an ASCII .pcd file, and the vertices of an ASCII .ply file with a plain header, read on all
  *   threads (readPcdAsciiData(), plainAsciiPlyLayout(), readAsciiRows());
  * - .xyz and .txt: lines of x y z and further columns, as many on every line (blank lines and
  *   # comments skipped). Three further columns are normals when each row's are of unit length,
  *   colours when they are whole numbers from 0 to 255; six are both, in either order; any other
  *   column is a field named by its number ("field4");
  * - .off (COFF/NOFF/CNOFF colours and normals kept) and .obj ("v x y z r g b" colours and "vn"
  *   normals kept): the vertices.
  * Coordinates are kept in double precision; point i is the i-th point (data line) of the file.
  * \param[in] weight_field for .pcd and .ply, the field holding the weights (empty: none)
  * \param[in] weights_column for .xyz and .txt, whether the 4th column holds the weights
  * \throws FileError when the file is unreadable, empty or malformed, or the weights asked for
  *         are not there or not allowed for the format. A non-finite weight is not an error: the
  *         construction skips its point. */
PointFile
readPointFile (const std::string& path, const std::string& weight_field = "", bool weights_column = false);

/** \brief The points of readPointFile(), without weights. */
std::vector<Point3>
readPoints (const std::string& path);

} // namespace pcl_wrap::apps
