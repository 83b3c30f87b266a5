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

/** \brief The numbers of a .xyz or .txt file: a point a line, x y z then any further columns. */
struct XyzTable
{
  std::vector<double> values; ///< row by row, columns numbers a row
  std::size_t columns = 0;    ///< numbers a line (0: no line has one)
  std::string error;          ///< "line N: ..." of the first line that does not read (then no values)
};

/** \brief Reads the lines of a .xyz or .txt file's text as parseNumbers() reads each, on all threads:
  * blank and comment lines skipped, every other line at least 3 numbers and as many as the first.
  * The values are those of std::strtod, bit for bit; the error is the first line's in the file.
  * The text comes in pieces of whole lines, in order, so that a large file need not be held
  * whole. */
class XyzParser
{
public:
  /** \param[in] chunk_bytes how much text a task reads, at least (on to the end of a line) */
  explicit XyzParser (std::size_t chunk_bytes = std::size_t (1) << 18);

  /** \brief Reads the next piece [first, last): whole lines (only the text's last may lack its
    * '\n'). False once a line has failed: later pieces are then not read. */
  bool parse (const char* first, const char* last);

  /** \brief Room for the table of a text of which \a share has been read, so that a large table is
    * not copied as it grows. */
  void reserveFor (double share);

  /** \brief What was read; the parser is empty after. */
  XyzTable take ();

private:
  std::size_t chunk_bytes_;
  XyzTable table_;
  std::size_t lines_ = 0; ///< lines read so far
};

/** \brief The table of a stream's text, read a window at a time by one XyzParser: the text is not
  * held whole, and the table has room for all of it from the first window on.
  * \param[in] bytes the stream's length if known (0 if not), to make that room
  * \param[in] window_bytes the most text read at once */
XyzTable
readXyzStream (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes = std::size_t (1) << 25);

/** \brief A whole text read by one XyzParser. */
XyzTable
parseXyzText (const std::string& text, std::size_t chunk_bytes = std::size_t (1) << 18);

} // namespace pcl_wrap::apps
