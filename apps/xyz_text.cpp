// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "xyz_text.h"

#include "text_line.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <charconv>
#include <cstring>
#include <limits>
#include <string_view>

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

/** The problem of a line of \a count numbers after lines of \a columns. */
std::string
widthProblem (std::size_t count, std::size_t columns)
{
  return std::to_string (count) + " numbers where earlier lines have " + std::to_string (columns);
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
readChunk (std::string_view text, Chunk& chunk)
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
      problem = widthProblem (count, chunk.columns);
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

XyzParser::XyzParser (std::size_t chunk_bytes) : chunk_bytes_ (std::max<std::size_t> (chunk_bytes, 1)) {}

bool
XyzParser::parse (const char* first, const char* last)
{
  if (!table_.error.empty ())
    return false;
  // Whole lines to each task: a chunk ends after the first '\n' at or past its share.
  const std::string_view text (first, std::size_t (last - first));
  std::vector<Chunk> chunks;
  for (std::size_t at = 0; at < text.size ();)
  {
    std::size_t end = std::min (text.size (), at + chunk_bytes_);
    if (end < text.size ())
    {
      const std::size_t eol = text.find ('\n', end);
      end = eol == std::string_view::npos ? text.size () : eol + 1;
    }
    chunks.emplace_back ().begin = at;
    chunks.back ().end = end;
    at = end;
  }
  tbb::parallel_for (std::size_t (0), chunks.size (), [&] (std::size_t k) { readChunk (text, chunks[k]); });

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
  XyzParser parser;
  std::string window; // the text not parsed yet: a line's start, then what is read after it
  window_bytes = std::max<std::size_t> (window_bytes, 1);
  // A small text is read at once; one of unknown length in steps that double up to a window.
  std::size_t step = bytes > 0 ? std::size_t (std::min<std::uintmax_t> (window_bytes, bytes + 1))
                               : std::min<std::size_t> (window_bytes, std::size_t (1) << 16);
  bool first = true;
  for (bool reading = true; reading; step = std::min (2 * step, window_bytes))
  {
    const std::size_t kept = window.size ();
    window.resize (kept + step);
    reading = in.read (window.data () + kept, std::streamsize (step)) || in.gcount () > 0;
    window.resize (kept + std::size_t (in.gcount ()));
    // Whole lines; at the end of the text, the last line too.
    const std::size_t whole = reading ? window.rfind ('\n') + 1 : window.size ();
    if (whole == 0)
      continue; // no '\n' yet (std::string::npos + 1)
    if (!parser.parse (window.data (), window.data () + whole))
      break;
    if (first && reading && bytes > whole)
      parser.reserve (std::size_t (double (parser.table ().values.size ()) * double (bytes) / double (whole) * 1.02) +
                      64);
    first = false;
    window.erase (0, whole);
  }
  return parser.take ();
}

XyzTable
parseXyzText (const std::string& text, std::size_t chunk_bytes)
{
  XyzParser parser (chunk_bytes);
  parser.parse (text.data (), text.data () + text.size ());
  return parser.take ();
}

} // namespace pcl_wrap::apps
