// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "obj_text.h"

#include "text_pieces.h"

#include <string_view>

namespace pcl_wrap::apps
{
namespace
{

/** One task's whole lines and what it made of them. */
struct Chunk : TextPiece
{
  ObjVertices read; ///< its error without "line N: "
};

bool
isBlank (char c)
{
  return c == ' ' || c == '\t';
}

/** The numbers after a keyword that ends at \a first, on the line up to \a last, into \a numbers. */
bool
numbersAfter (const char* first, const char* last, std::vector<double>& numbers)
{
  numbers.clear ();
  std::size_t count;
  return appendNumbers (first, last, numbers, count);
}

/** Reads the lines of \a chunk as the file's reader would if they came first. */
void
readChunk (std::string_view text, Chunk& chunk)
{
  ObjVertices& read = chunk.read;
  std::vector<double> numbers;
  readLines (text, chunk, [&] (const char* first, const char* last) {
    const char* start = first;
    while (start < last && isBlank (*start))
      ++start;
    const char* end = start;
    while (end < last && !isBlank (*end))
      ++end;
    const std::string_view keyword (start, std::size_t (end - start));
    if (end == last || (keyword != "v" && keyword != "vn"))
      return true; // no keyword followed by whitespace, or one that is not read
    const bool ok = numbersAfter (end, last, numbers);
    if (keyword == "vn")
    {
      if (!ok || numbers.size () != 3)
        read.error = "a normal needs 3 numbers";
      else
        read.normals.insert (read.normals.end (), {float (numbers[0]), float (numbers[1]), float (numbers[2])});
    }
    else if (!ok || numbers.size () < 3 || numbers.size () > 7)
      read.error = "a vertex needs 3 coordinates";
    else
    {
      read.points.insert (read.points.end (), numbers.begin (), numbers.begin () + 3);
      read.every_vertex_coloured = read.every_vertex_coloured && numbers.size () == 6; // "v x y z r g b"
      if (read.every_vertex_coloured)
        read.colours.insert (read.colours.end (), numbers.begin () + 3, numbers.end ());
    }
    return read.error.empty ();
  });
}

/** Appends \a from to \a to. */
template <class T>
void
append (std::vector<T>& to, const std::vector<T>& from)
{
  to.insert (to.end (), from.begin (), from.end ());
}

} // namespace

ObjParser::ObjParser (std::size_t chunk_bytes) : chunk_bytes_ (chunk_bytes) {}

bool
ObjParser::parse (const char* first, const char* last)
{
  if (!read_.error.empty ())
    return false;
  const std::vector<Chunk> chunks =
      readPieces<Chunk> (std::string_view (first, std::size_t (last - first)), chunk_bytes_, readChunk);
  // In file order, up to the first failing line.
  for (const Chunk& chunk : chunks)
  {
    if (chunk.error_line != NO_LINE)
    {
      read_ = {};
      read_.error = "line " + std::to_string (lines_ + chunk.error_line + 1) + ": " + chunk.read.error;
      return false;
    }
    append (read_.points, chunk.read.points);
    append (read_.normals, chunk.read.normals);
    read_.every_vertex_coloured = read_.every_vertex_coloured && chunk.read.every_vertex_coloured;
    if (read_.every_vertex_coloured)
      append (read_.colours, chunk.read.colours);
    else
      read_.colours = {};
    lines_ += chunk.lines;
  }
  return true;
}

void
ObjParser::reserveFor (double share)
{
  const auto room = [&] (std::size_t size) { return std::size_t (double (size) / share * 1.02) + 64; };
  read_.points.reserve (room (read_.points.size ()));
  read_.normals.reserve (room (read_.normals.size ()));
  if (read_.every_vertex_coloured)
    read_.colours.reserve (room (read_.colours.size ()));
}

ObjVertices
ObjParser::take ()
{
  ObjVertices out = std::move (read_);
  read_ = {};
  lines_ = 0;
  return out;
}

ObjVertices
readObjStream (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes)
{
  return readWithParser (ObjParser (), in, bytes, window_bytes);
}

ObjVertices
parseObjText (const std::string& text, std::size_t chunk_bytes)
{
  ObjParser parser (chunk_bytes);
  parser.parse (text.data (), text.data () + text.size ());
  return parser.take ();
}

} // namespace pcl_wrap::apps
