// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "xyz_text.h"

#include "text_line.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <limits>

namespace pcl_wrap::apps
{
namespace
{

constexpr std::size_t NO_LINE = std::numeric_limits<std::size_t>::max ();

/** What separates tokens: std::isspace in the "C" locale, as for the streams of parseNumbers(). */
bool
isSpace (char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/** The number that is the whole token [first, last), as parseNumbers() reads it; false if it
  * reads none. A plain decimal is read with std::from_chars, which rounds correctly as strtod
  * does and is several times faster; anything else (a sign '+', hexadecimal, inf, nan, out of
  * range, a byte no number has) is handed to parseNumbers() itself. */
bool
tokenValue (const char* first, const char* last, double& value)
{
  const char* digits = first + (*first == '-');
  if (digits < last && (*digits == '.' || (*digits >= '0' && *digits <= '9')))
  {
    const auto [end, ec] = std::from_chars (first, last, value);
    if (ec == std::errc () && end == last)
      return true;
  }
  static thread_local std::vector<double> one;
  if (!parseNumbers (std::string (first, last), one) || one.size () != 1)
    return false;
  value = one[0];
  return true;
}

/** Appends the numbers of the line [first, last) (no '\n' in it) to \a out; false where
  * parseNumbers() would return false. \a count: how many it read. */
bool
readLine (const char* first, const char* last, std::vector<double>& out, std::size_t& count)
{
  if (const void* hash = std::memchr (first, '#', std::size_t (last - first)))
    last = static_cast<const char*> (hash);
  count = 0;
  for (const char* p = first;;)
  {
    while (p < last && isSpace (*p))
      ++p;
    if (p == last)
      return true;
    const char* end = p;
    while (end < last && !isSpace (*end))
      ++end;
    double value;
    if (!tokenValue (p, end, value))
      return false;
    out.push_back (value);
    ++count;
    p = end;
  }
}

/** One task's whole lines and what it made of them. */
struct Chunk
{
  std::size_t begin = 0, end = 0; ///< bytes of the text
  std::vector<double> values;
  std::size_t lines = 0;            ///< lines read (all of them, unless one failed)
  std::size_t columns = 0;          ///< of the first line with numbers
  std::size_t first_line = NO_LINE; ///< that line, from the chunk's first
  std::size_t error_line = NO_LINE; ///< the first line that failed, from the chunk's first
  std::string error;                ///< its problem, without "line N: "
};

/** Reads the lines of \a chunk as the file's reader would if they came first. */
void
readChunk (const std::string& text, Chunk& chunk)
{
  const char* p = text.data () + chunk.begin;
  const char* const stop = text.data () + chunk.end;
  std::size_t count = 0;
  for (; p < stop; ++chunk.lines)
  {
    const char* eol = static_cast<const char*> (std::memchr (p, '\n', std::size_t (stop - p)));
    if (!eol)
      eol = stop;
    const std::size_t before = chunk.values.size ();
    std::string problem;
    if (!readLine (p, eol, chunk.values, count))
      problem = "not a number";
    else if (count > 0 && count < 3)
      problem = "expected at least 3 numbers (x y z ...), found " + std::to_string (count);
    else if (count > 0 && chunk.columns != 0 && count != chunk.columns)
      problem = std::to_string (count) + " numbers where earlier lines have " + std::to_string (chunk.columns);
    if (!problem.empty ())
    {
      chunk.values.resize (before);
      chunk.error_line = chunk.lines;
      chunk.error = std::move (problem);
      return;
    }
    if (count > 0 && chunk.columns == 0)
    {
      chunk.columns = count;
      chunk.first_line = chunk.lines;
    }
    p = eol + 1;
  }
}

} // namespace

XyzTable
parseXyzText (const std::string& text, std::size_t chunk_bytes)
{
  chunk_bytes = std::max<std::size_t> (chunk_bytes, 1);
  // Whole lines to each task: a chunk ends after the first '\n' at or past its share.
  std::vector<Chunk> chunks;
  for (std::size_t at = 0; at < text.size ();)
  {
    std::size_t end = std::min (text.size (), at + chunk_bytes);
    if (end < text.size ())
    {
      const void* eol = std::memchr (text.data () + end, '\n', text.size () - end);
      end = eol ? std::size_t (static_cast<const char*> (eol) - text.data ()) + 1 : text.size ();
    }
    chunks.emplace_back ().begin = at;
    chunks.back ().end = end;
    at = end;
  }
  tbb::parallel_for (std::size_t (0), chunks.size (), [&] (std::size_t k) { readChunk (text, chunks[k]); });

  // In file order: the first failing line, seen across chunks; a chunk's first line with numbers
  // must also have as many as the lines before it.
  XyzTable table;
  std::size_t lines_before = 0, rows = 0;
  for (const Chunk& chunk : chunks)
  {
    const bool mismatch = chunk.columns != 0 && table.columns != 0 && chunk.columns != table.columns;
    if (mismatch && chunk.first_line < chunk.error_line)
    {
      table.error = "line " + std::to_string (lines_before + chunk.first_line + 1) + ": " +
                    std::to_string (chunk.columns) + " numbers where earlier lines have " +
                    std::to_string (table.columns);
      table.columns = 0;
      return table;
    }
    if (chunk.error_line != NO_LINE)
    {
      table.error = "line " + std::to_string (lines_before + chunk.error_line + 1) + ": " + chunk.error;
      table.columns = 0;
      return table;
    }
    if (table.columns == 0)
      table.columns = chunk.columns;
    lines_before += chunk.lines;
    rows += chunk.columns == 0 ? 0 : chunk.values.size () / chunk.columns;
  }
  table.values.resize (rows * table.columns);
  std::vector<std::size_t> offset (chunks.size () + 1, 0);
  for (std::size_t k = 0; k < chunks.size (); ++k)
    offset[k + 1] = offset[k] + chunks[k].values.size ();
  tbb::parallel_for (std::size_t (0), chunks.size (), [&] (std::size_t k) {
    std::copy (chunks[k].values.begin (), chunks[k].values.end (), table.values.begin () + std::ptrdiff_t (offset[k]));
  });
  return table;
}

} // namespace pcl_wrap::apps
