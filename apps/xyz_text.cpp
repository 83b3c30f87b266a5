// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "xyz_text.h"

#include "text_pieces.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <string_view>

namespace pcl_wrap::apps
{
namespace
{

/** The problem of a line of \a count numbers after lines of \a columns. */
std::string
widthProblem (std::size_t count, std::size_t columns)
{
  return std::to_string (count) + " numbers where earlier lines have " + std::to_string (columns);
}

/** One task's whole lines and what it made of them. */
struct Chunk : TextPiece
{
  std::vector<double> values;
  std::size_t columns = 0;          ///< of the first line with numbers
  std::size_t first_line = NO_LINE; ///< that line, from the chunk's first
  std::string error;                ///< the problem of its error_line, without "line N: "
};

/** Reads the lines of \a chunk as the file's reader would if they came first. */
void
readChunk (std::string_view text, Chunk& chunk)
{
  readLines (text, chunk, [&] (const char* first, const char* last) {
    std::size_t count = 0;
    if (!appendNumbers (first, last, chunk.values, count))
      chunk.error = "not a number";
    else if (count > 0 && count < 3)
      chunk.error = "expected at least 3 numbers (x y z ...), found " + std::to_string (count);
    else if (count > 0 && chunk.columns != 0 && count != chunk.columns)
      chunk.error = widthProblem (count, chunk.columns);
    if (!chunk.error.empty ())
    {
      chunk.values.resize (chunk.values.size () - count);
      return false;
    }
    if (count > 0 && chunk.columns == 0)
    {
      chunk.columns = count;
      chunk.first_line = chunk.lines;
    }
    return true;
  });
}

} // namespace

XyzParser::XyzParser (std::size_t chunk_bytes) : chunk_bytes_ (std::max<std::size_t> (chunk_bytes, 1)) {}

bool
XyzParser::parse (const char* first, const char* last)
{
  if (!table_.error.empty ())
    return false;
  const std::vector<Chunk> chunks =
      readPieces<Chunk> (std::string_view (first, std::size_t (last - first)), chunk_bytes_, readChunk);

  // In file order: the first failing line, seen across chunks; a chunk's first line with numbers
  // must also have as many as the lines before it.
  for (const Chunk& chunk : chunks)
  {
    const bool mismatch = chunk.columns != 0 && table_.columns != 0 && chunk.columns != table_.columns;
    if (mismatch && chunk.first_line < chunk.error_line)
      table_.error = "line " + std::to_string (lines_ + chunk.first_line + 1) + ": " +
                     widthProblem (chunk.columns, table_.columns);
    else if (chunk.error_line != NO_LINE)
      table_.error = "line " + std::to_string (lines_ + chunk.error_line + 1) + ": " + chunk.error;
    if (!table_.error.empty ())
    {
      table_.values = {};
      table_.columns = 0;
      return false;
    }
    if (table_.columns == 0)
      table_.columns = chunk.columns;
    lines_ += chunk.lines;
  }
  std::vector<std::size_t> offset (chunks.size () + 1, table_.values.size ());
  for (std::size_t k = 0; k < chunks.size (); ++k)
    offset[k + 1] = offset[k] + chunks[k].values.size ();
  table_.values.resize (offset.back ());
  tbb::parallel_for (std::size_t (0), chunks.size (), [&] (std::size_t k) {
    std::copy (chunks[k].values.begin (), chunks[k].values.end (), table_.values.begin () + std::ptrdiff_t (offset[k]));
  });
  return true;
}

void
XyzParser::reserveFor (double share)
{
  table_.values.reserve (std::size_t (double (table_.values.size ()) / share * 1.02) + 64);
}

XyzTable
XyzParser::take ()
{
  XyzTable out = std::move (table_);
  table_ = {};
  lines_ = 0;
  return out;
}

XyzTable
readXyzStream (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes)
{
  return readWithParser (XyzParser (), in, bytes, window_bytes);
}

XyzTable
parseXyzText (const std::string& text, std::size_t chunk_bytes)
{
  XyzParser parser (chunk_bytes);
  parser.parse (text.data (), text.data () + text.size ());
  return parser.take ();
}

} // namespace pcl_wrap::apps
