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

/** \brief The vertices and normals of a Wavefront .obj file's text. */
struct ObjVertices
{
  std::vector<double> points;        ///< x y z of each "v" line
  std::vector<double> colours;       ///< r g b of each "v" line, while each has exactly 6 numbers
  bool every_vertex_coloured = true; ///< every "v" line has 6 numbers: colours holds them all
  std::vector<float> normals;        ///< x y z of each "vn" line
  std::string error;                 ///< "line N: ..." of the first line that does not read (then nothing else)
};

/** \brief Reads the "v" and "vn" lines of a .obj file's text on all threads, as one reading a line
  * at a time with parseNumbers() would: a line's keyword is its first word when whitespace
  * follows it; a "v" line has 3 to 7 numbers, a "vn" line 3; every other line is skipped. The
  * values are those of std::strtod, bit for bit; the error is the first line's in the file. The
  * text comes in pieces of whole lines, in order, so that a large file need not be held whole. */
class ObjParser
{
public:
  /** \param[in] chunk_bytes how much text a task reads, at least (on to the end of a line) */
  explicit ObjParser (std::size_t chunk_bytes = std::size_t (1) << 18);

  /** \brief Reads the next piece [first, last): whole lines (only the text's last may lack its
    * '\n'). False once a line has failed: later pieces are then not read. */
  bool parse (const char* first, const char* last);

  /** \brief Room for the vertices of a text of which \a share has been read. */
  void reserveFor (double share);

  /** \brief What was read; the parser is empty after. */
  ObjVertices take ();

private:
  std::size_t chunk_bytes_;
  ObjVertices read_;
  std::size_t lines_ = 0; ///< lines read so far
};

/** \brief The vertices of a stream's .obj text, read a window at a time by one ObjParser.
  * \param[in] bytes the stream's length if known (0 if not), to make room for them
  * \param[in] window_bytes the most text read at once */
ObjVertices
readObjStream (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes = std::size_t (1) << 25);

/** \brief A whole .obj text read by one ObjParser. */
ObjVertices
parseObjText (const std::string& text, std::size_t chunk_bytes = std::size_t (1) << 18);

} // namespace pcl_wrap::apps
