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

/** \brief Reads the data lines of an ASCII PCD file into \a cloud, a window of text at a time and
  * the lines of a window on all threads; returns what is wrong with them, or an empty string.
  *
  * \a cloud comes from PCL's pcl::PCDReader::readHeader() (fields, width, height, point_step, and
  * data sized for the points) and \a in stands at the data. A line with numbers is a point: one
  * number per value of its fields, in order, as parseNumbers() reads them (a '#' comment cut off);
  * a line with none is skipped. A float field holds the number rounded to float, as PCL's reader
  * stores it; an integer field holds a whole number that fits it (a BOOL field, 0 or 1). Padding
  * fields ("_") are skipped. Wrong where a line has a token that is not a
  * number, a line has a different count of numbers, a number does not fit its integer field, or
  * the file has more or fewer points than the header declares: the message names the first such
  * data line (counted from 1), where there is one.
  * \param[in] bytes the data's length if known (0 if not) */
std::string
readPcdAsciiData (std::istream& in, std::uintmax_t bytes, pcl::PCLPointCloud2& cloud,
                  std::size_t window_bytes = std::size_t (1) << 25, std::size_t chunk_bytes = std::size_t (1) << 18);

} // namespace pcl_wrap::apps
