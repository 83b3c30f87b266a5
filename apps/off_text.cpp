// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "off_text.h"

#include "text_line.h"
#include "text_pieces.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string_view>

namespace pcl_wrap::apps
{
namespace
{

constexpr const char* VERTICES = "all vertices are read";

/** One task's whole lines: the numbers of those that have any, up to the first that fails. */
struct Chunk : TextPiece
{
  std::vector<double> values;
  std::vector<std::size_t> row_end;  ///< per line with numbers, the end of its numbers in values
  std::vector<std::size_t> row_line; ///< per line with numbers, the line, from the chunk's first
};

/** Reads the numbers of \a chunk's lines, as the file's reader would. */
void
readChunk (std::string_view text, Chunk& chunk)
{
  readLines (text, chunk, [&] (const char* first, const char* last) {
    std::size_t count = 0;
    if (!appendNumbers (first, last, chunk.values, count))
      return false;
    if (count > 0)
    {
      chunk.row_end.push_back (chunk.values.size ());
      chunk.row_line.push_back (chunk.lines);
    }
    return true;
  });
}

/** The vertex lines of an .off text after its header, \a count of them, a piece at a time. */
class VertexRows
{
public:
  VertexRows (OffVertices& out, std::size_t count, std::size_t lines_before, std::size_t chunk_bytes)
    : out_ (out), count_ (count), lines_ (lines_before), chunk_bytes_ (chunk_bytes)
  {
    out_.begin.assign (1, 0);
  }

  std::size_t rows () const { return out_.begin.size () - 1; }
  bool done () const { return !out_.error.empty () || rows () == count_; }

  /** Reads the next piece of whole lines; false once done. */
  bool parse (const char* first, const char* last)
  {
    const std::vector<Chunk> chunks =
        readPieces<Chunk> (std::string_view (first, std::size_t (last - first)), chunk_bytes_, readChunk);
    // In file order: each vertex line with as many numbers as needed, up to the last vertex.
    for (const Chunk& chunk : chunks)
    {
      for (std::size_t r = 0; r < chunk.row_end.size () && !done (); ++r)
      {
        const std::size_t row_begin = r == 0 ? 0 : chunk.row_end[r - 1];
        if (chunk.row_end[r] - row_begin < out_.needed)
          return failAt (lines_ + chunk.row_line[r], "a vertex needs " + std::to_string (out_.needed) + " numbers");
        out_.values.insert (out_.values.end (), chunk.values.begin () + std::ptrdiff_t (row_begin),
                            chunk.values.begin () + std::ptrdiff_t (chunk.row_end[r]));
        out_.begin.push_back (out_.values.size ());
      }
      if (done ())
        return false;
      if (chunk.error_line != NO_LINE)
        return failAt (lines_ + chunk.error_line, std::string ("not a number in ") + VERTICES);
      lines_ += chunk.lines;
    }
    return true;
  }

private:
  /** The error; readOffStream() then empties the rest. */
  bool failAt (std::size_t line, const std::string& problem)
  {
    out_.error = "line " + std::to_string (line + 1) + ": " + problem;
    return false;
  }

  OffVertices& out_;
  std::size_t count_;
  std::size_t lines_; ///< lines before the next piece
  std::size_t chunk_bytes_;
};

} // namespace

bool
nextNumbersLine (std::istream& in, std::vector<double>& numbers, std::size_t& lines, const char* what,
                 std::string& problem)
{
  std::string line;
  while (std::getline (in, line))
  {
    ++lines;
    if (!parseNumbers (line, numbers))
    {
      problem = "line " + std::to_string (lines) + ": not a number in " + what;
      return false;
    }
    if (!numbers.empty ())
      return true;
  }
  problem = std::string ("ends before ") + what;
  return false;
}

OffHeader
readOffHeader (std::istream& in)
{
  OffHeader out;
  const auto fail = [&] (std::string problem) {
    out = {};
    out.error = std::move (problem);
    return out;
  };
  std::string line, keyword;
  while (keyword.empty () && std::getline (in, line))
  {
    ++out.lines;
    std::istringstream (line.substr (0, line.find ('#'))) >> keyword;
  }
  if (keyword.size () < 3 || keyword.compare (keyword.size () - 3, 3, "OFF") != 0)
    return fail ("not an OFF file (no OFF header)");
  // [ST][C][N][4][n]OFF: a vertex line is x y z [nx ny nz] [r g b [a]] [s t].
  const std::string prefix = keyword.substr (0, keyword.size () - 3);
  out.normals = prefix.find ('N') != std::string::npos;
  out.colours = prefix.find ('C') != std::string::npos;
  out.needed = 3 + (out.normals ? 3 : 0) + (out.colours ? 3 : 0);
  // The counts may follow the keyword on its line.
  std::istringstream rest (line.substr (line.find ("OFF") + 3));
  double count = 0;
  if (!(rest >> count))
  {
    std::vector<double> numbers;
    std::string problem;
    if (!nextNumbersLine (in, numbers, out.lines, "the vertex count", problem))
      return fail (problem);
    count = numbers[0];
  }
  if (!(count >= 0 && count <= 4.0e9 && count == std::floor (count)))
    return fail ("bad vertex count");
  out.vertices = static_cast<std::size_t> (count);
  return out;
}

OffVertices
readOffStream (std::istream& in, std::size_t window_bytes, std::size_t chunk_bytes)
{
  OffVertices out;
  const auto fail = [&] (std::string problem) { // a copy: it may be out's own
    out = {};
    out.error = std::move (problem);
    return out;
  };
  const OffHeader header = readOffHeader (in);
  if (!header.error.empty ())
    return fail (header.error);
  out.normals = header.normals;
  out.colours = header.colours;
  out.needed = header.needed;
  const std::size_t vertices = header.vertices;
  out.values.reserve (std::min<std::size_t> (vertices, 10000000) * out.needed);
  VertexRows rows (out, vertices, header.lines, chunk_bytes);
  if (!rows.done ())
    readInWindows (in, 0, window_bytes,
                   [&] (const char* first, const char* last, double) { return rows.parse (first, last); });
  if (!out.error.empty ())
    return fail (out.error);
  if (!rows.done ())
    return fail (std::string ("ends before ") + VERTICES);
  return out;
}

} // namespace pcl_wrap::apps
