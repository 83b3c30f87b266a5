// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "ascii_rows.h"

#include <pcl/PCLPointCloud2.h>

#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief The cloud that PCL's PLY reader makes of the vertices of an ASCII PLY file, and where
  * each number of a vertex line goes in it. */
struct PlyVertexLayout
{
  pcl::PCLPointCloud2 cloud;    ///< fields, width (the vertices), height 1, point_step; data sized
  std::vector<RowValue> values; ///< per property of a vertex
  std::uint64_t data_start = 0; ///< the first byte after the header
};

/** \brief The pcl::PCLPointField type of a PLY scalar type's name ("float", "uchar", "int32", ...),
  * or 0 for none. */
std::uint8_t
plyFieldType (const std::string& type);

/** \brief The layout of an ASCII PLY file's vertices, read from its header in \a in, where the
  * header is a plain one: "vertex" its first element, with scalar properties only, colours as
  * consecutive uchar red, green, blue and optionally alpha, no "camera" or "range_grid" element,
  * no '\\r'. Otherwise nothing: such a file is left to PCL's reader. Unlike PCL's reader, it gives
  * the vertices whatever obj_info's num_cols and num_rows say: PCL's ASCII writer leaves a cloud's
  * NaN points out of the vertices but not out of num_cols, where PCL's reader would make points of
  * zeros of them.
  *
  * The fields are PCL's: each property its own, of its type, but uchar red, green and blue one
  * FLOAT32 field "rgb" (its bytes blue, green, red, 0), with alpha one UINT32 field "rgba" (alpha
  * its fourth byte); a uchar intensity a FLOAT32 field; nx, ny and nz named normal_x, normal_y and
  * normal_z. */
std::optional<PlyVertexLayout>
plainAsciiPlyLayout (std::istream& in);

} // namespace pcl_wrap::apps
