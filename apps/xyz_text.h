// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief The numbers of a .xyz or .txt file: a point a line, x y z then any further columns. */
struct XyzTable
{
  std::vector<double> values; ///< row by row, columns numbers a row
  std::size_t columns = 0;    ///< numbers a line (0: no line has one)
  std::string error;          ///< "line N: ..." of the first line that does not read (then no values)
};

/** \brief The lines of \a text read as parseNumbers() reads each, on all threads: blank and
  * comment lines skipped, every other line at least 3 numbers and as many as the first. The
  * values are those of std::strtod, bit for bit; the error is the first line's in the file.
  * \param[in] chunk_bytes how much text a task reads, at least (on to the end of a line) */
XyzTable
parseXyzText (const std::string& text, std::size_t chunk_bytes = std::size_t (1) << 18);

} // namespace pcl_wrap::apps
