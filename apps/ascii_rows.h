// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief One number of a data row of an ASCII point file, and where it goes in a point of a PCL
  * cloud's data. */
struct RowValue
{
  std::string field;      ///< the name of its field, for messages
  std::uint8_t read_as;   ///< a pcl::PCLPointField type: an integer type takes whole numbers that fit it
  std::uint8_t stored_as; ///< a pcl::PCLPointField type, at offset
  std::uint32_t offset;   ///< in a point's bytes
  bool skipped = false;   ///< a padding value: read, not stored
};

/** \brief Reads the data rows of an ASCII point file into \a data, a window of text at a time and
  * the lines of a window on all threads; returns what is wrong with them, or an empty string.
  *
  * The first \a rows lines with numbers (as parseNumbers() reads them, a '#' comment cut off) are
  * the rows, each of one number per value of \a values, stored at row * \a point_step (\a data
  * holds \a rows points): the float nearest to the number where read as a float, an integer
  * type's whole number that fits it (a BOOL's, 0 or 1), stored as read or, from an integer type,
  * as a float. Lines with no number are skipped. Further lines with numbers are an error, unless
  * \a more_follow (a PLY file's other elements), where their tokens need only be numbers. Wrong
  * where a token is not a number, a row has a different count of numbers or a number that does
  * not fit its type, or there are fewer rows (or, without \a more_follow, more): the message
  * names the first such data line, counted from 1, where there is one.
  * \param[in] bytes the data's length if known (0 if not) */
std::string
readAsciiRows (std::istream& in, std::uintmax_t bytes, const std::vector<RowValue>& values, std::size_t point_step,
               std::size_t rows, bool more_follow, std::vector<std::uint8_t>& data,
               std::size_t window_bytes = std::size_t (1) << 25, std::size_t chunk_bytes = std::size_t (1) << 18);

} // namespace pcl_wrap::apps
