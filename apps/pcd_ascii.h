// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl/PCLPointCloud2.h>

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>

namespace pcl_wrap::apps
{

/** \brief Reads the data lines of an ASCII PCD file into \a cloud, on all threads
  * (readAsciiRows()): a point per line with numbers, one number per value of its fields, in
  * order; padding fields ("_") skipped. Returns what is wrong with them, or an empty string.
  * \param[in] bytes the data's length if known (0 if not)
  * \param[in,out] cloud from PCL's pcl::PCDReader::readHeader() (fields, width, height,
  *            point_step; data sized for the points), \a in standing at its data */
std::string
readPcdAsciiData (std::istream& in, std::uintmax_t bytes, pcl::PCLPointCloud2& cloud,
                  std::size_t window_bytes = std::size_t (1) << 25, std::size_t chunk_bytes = std::size_t (1) << 18);

} // namespace pcl_wrap::apps
