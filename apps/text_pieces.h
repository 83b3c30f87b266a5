// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <tbb/parallel_for.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <istream>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief What separates tokens: std::isspace in the "C" locale, as for the streams of
  * parseNumbers(). */
inline bool
isTokenSpace (char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\v' || c == '\f' || c == '\r';
}

/** \brief Calls \a token (first, last) on each whitespace-separated token of the line [first, last)
  * (no '\n' in it) in turn, a '#' comment cut off, as parseNumbers() cuts a line, until one
  * returns false; returns whether none did. */
template <class Token>
bool
forEachToken (const char* first, const char* last, const Token& token)
{
  if (const void* hash = std::memchr (first, '#', std::size_t (last - first)))
    last = static_cast<const char*> (hash);
  for (const char* p = first;;)
  {
    while (p < last && isTokenSpace (*p))
      ++p;
    if (p == last)
      return true;
    const char* end = p;
    while (end < last && !isTokenSpace (*end))
      ++end;
    if (!token (p, end))
      return false;
    p = end;
  }
}

/** \brief The number that is the whole token [first, last) (not empty, no whitespace in it), as
  * parseNumbers() reads a token, bit for bit; false if it reads none. */
bool
tokenValue (const char* first, const char* last, double& value);

/** \brief The numbers of the line [first, last) (no '\n' in it), appended to \a out, as
  * parseNumbers() reads them: a '#' comment cut off, whitespace-separated tokens, each read as
  * std::strtod reads it, bit for bit. False, with \a out as it was, where parseNumbers() returns
  * false; \a count: how many numbers it appended. */
bool
appendNumbers (const char* first, const char* last, std::vector<double>& out, std::size_t& count);

/** \brief The text cut into pieces of whole lines for tasks, as [begin, end) byte offsets: each at
  * least \a chunk_bytes long, on to the end of a line, but the last. */
std::vector<std::pair<std::size_t, std::size_t>>
wholeLinePieces (std::string_view text, std::size_t chunk_bytes);

/** \brief No line: where a piece has no failing line. */
constexpr std::size_t NO_LINE = std::numeric_limits<std::size_t>::max ();

/** \brief A task's piece of a text, whole lines; what a reader makes of them goes in a struct
  * derived from it. */
struct TextPiece
{
  std::size_t begin = 0, end = 0;   ///< bytes of the text
  std::size_t lines = 0;            ///< lines read (all of them, unless one failed)
  std::size_t error_line = NO_LINE; ///< the first line that failed, from the piece's first
};

/** \brief Calls \a line (first, last) on each line of \a piece of \a text in turn (no '\n' in
  * it), while piece.lines counts them, until one returns false: that one is piece.error_line. */
template <class Line>
void
readLines (std::string_view text, TextPiece& piece, const Line& line)
{
  const char* p = text.data () + piece.begin;
  const char* const stop = text.data () + piece.end;
  for (; p < stop; ++piece.lines)
  {
    const char* eol = static_cast<const char*> (std::memchr (p, '\n', std::size_t (stop - p)));
    if (!eol)
      eol = stop;
    if (!line (p, eol))
    {
      piece.error_line = piece.lines;
      return;
    }
    p = eol + 1;
  }
}

/** \brief The text cut into pieces (wholeLinePieces()) of type \a Piece, a TextPiece, each read
  * by \a read (text, piece) on all threads; in order. */
template <class Piece, class Read>
std::vector<Piece>
readPieces (std::string_view text, std::size_t chunk_bytes, const Read& read)
{
  std::vector<Piece> pieces;
  for (const auto& [begin, end] : wholeLinePieces (text, chunk_bytes))
  {
    pieces.emplace_back ().begin = begin;
    pieces.back ().end = end;
  }
  tbb::parallel_for (std::size_t (0), pieces.size (), [&] (std::size_t k) { read (text, pieces[k]); });
  return pieces;
}

/** \brief Reads a stream's text a window at a time and hands \a parse its whole lines in order
  * (the text's last line too, whether or not it ends in '\n'), so that a large text is never held
  * whole. A small text is read at once; one of unknown length in steps that double up to a
  * window. \a parse gets the lines and, after the first window of a longer text, the share of the
  * text they are (else 0), so that it can make room for the rest; it returns false to stop.
  * \param[in] bytes the stream's length if known (0 if not) */
void
readInWindows (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes,
               const std::function<bool (const char* first, const char* last, double share)>& parse);

/** \brief The first line, counted from 0, of a stream's text with a token that is not a number
  * as parseNumbers() reads it (a '#' comment cut off), or NO_LINE: read a window at a time
  * (readInWindows()), the lines of a window on all threads.
  * \param[in] bytes the stream's length if known (0 if not) */
std::size_t
firstLineNotNumbers (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes = std::size_t (1) << 25,
                     std::size_t chunk_bytes = std::size_t (1) << 18);

/** \brief What \a parser reads of a stream's text, handed to it a window at a time
  * (readInWindows()): its parse (first, last) gets the whole lines, its reserveFor (share) is told
  * what share of a text of known length the first window was, and its take () gives the result.
  * \param[in] bytes the stream's length if known (0 if not) */
template <class Parser>
auto
readWithParser (Parser parser, std::istream& in, std::uintmax_t bytes, std::size_t window_bytes)
{
  readInWindows (in, bytes, window_bytes, [&] (const char* first, const char* last, double share) {
    if (!parser.parse (first, last))
      return false;
    if (share > 0)
      parser.reserveFor (share);
    return true;
  });
  return parser.take ();
}

} // namespace pcl_wrap::apps
