// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "ascii_rows.h"

#include "text_pieces.h"

#include <pcl/PCLPointField.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <vector>

namespace pcl_wrap::apps
{
namespace
{

/** \a value rounded to float as IEEE arithmetic rounds it, beyond the largest float too (where a
  * cast is undefined). */
float
toFloat (double value)
{
  const double size = std::fabs (value);
  if (!(size > std::numeric_limits<float>::max ()) || std::isinf (size))
    return static_cast<float> (value);
  // Half a unit in the last place above the largest float: from there on, infinity.
  return static_cast<float> (std::copysign (size < 0x1.ffffffp127 ? std::numeric_limits<float>::max ()
                                                                  : std::numeric_limits<double>::infinity (),
                                            value));
}

/** The float nearest to the number token [first, last), whose double is \a number, as std::strtof
  * reads it: not the double nearest to it rounded again, which can be a float further off. */
float
nearestFloat (const char* first, const char* last, double number)
{
  const char* digits = first + (*first == '+' && last - first > 1 && first[1] != '-' && first[1] != '+');
  float single;
  const auto [end, ec] = std::from_chars (digits, last, single);
  if (ec == std::errc () && end == last)
    return single;
  return toFloat (number); // hexadecimal, or beyond a float's range
}

/** The whole number of type T that the number token [first, last), whose double is \a value, is,
  * if it is one that T holds. */
template <class T>
bool
wholeNumber (const char* first, const char* last, double value, T& out)
{
  const auto [end, ec] = std::from_chars (first, last, out);
  if (ec == std::errc () && end == last)
    return true;
  if (value != std::floor (value))
    return false;
  // T's range, as powers of two that a double holds exactly.
  constexpr int bits = std::numeric_limits<T>::digits;
  const double below = std::numeric_limits<T>::is_signed ? -std::ldexp (1.0, bits) : 0.0;
  if (!(value >= below && value < std::ldexp (1.0, bits)))
    return false;
  out = static_cast<T> (value);
  return true;
}

/** Stores the number token [first, last), whose double is \a number, at \a point + the value's
  * offset, as its type; false where it does not fit an integer type. */
bool
storeValue (const char* first, const char* last, double number, const RowValue& value, std::uint8_t* point)
{
  std::uint8_t* at = point + value.offset;
  // An integer read, stored as its own type or as a float.
  const auto whole = [&] (auto integer) {
    if (!wholeNumber (first, last, number, integer))
      return false;
    if (value.stored_as == pcl::PCLPointField::FLOAT32)
    {
      const auto single = static_cast<float> (integer);
      std::memcpy (at, &single, sizeof single);
    }
    else
      std::memcpy (at, &integer, sizeof integer);
    return true;
  };
  switch (value.read_as)
  {
  case pcl::PCLPointField::INT8: return whole (std::int8_t ());
  case pcl::PCLPointField::UINT8: return whole (std::uint8_t ());
  case pcl::PCLPointField::INT16: return whole (std::int16_t ());
  case pcl::PCLPointField::UINT16: return whole (std::uint16_t ());
  case pcl::PCLPointField::INT32: return whole (std::int32_t ());
  case pcl::PCLPointField::UINT32: return whole (std::uint32_t ());
  case pcl::PCLPointField::INT64: return whole (std::int64_t ());
  case pcl::PCLPointField::UINT64: return whole (std::uint64_t ());
  case pcl::PCLPointField::BOOL:
  {
    std::uint8_t flag;
    if (!wholeNumber (first, last, number, flag) || flag > 1)
      return false;
    *at = flag;
    return true;
  }
  case pcl::PCLPointField::FLOAT32:
  {
    const float single = nearestFloat (first, last, number);
    std::memcpy (at, &single, sizeof single);
    return true;
  }
  case pcl::PCLPointField::FLOAT64: std::memcpy (at, &number, sizeof number); return true;
  default: return false;
  }
}

/** One task's whole lines: per line with numbers, the row it makes or what is wrong with it as
  * one (a later element's line need not be a row). */
struct Piece : TextPiece
{
  std::vector<std::uint8_t> data;        ///< the rows, one after another
  std::vector<std::size_t> number_lines; ///< the lines with numbers, from the piece's first
  std::vector<std::uint32_t> problem;    ///< per line with numbers: 0 for a row, else problems[i - 1]
  std::vector<std::string> problems;
  std::string error; ///< the problem of its error_line: a token that is not a number
};

void
readPiece (std::string_view text, Piece& piece, const std::vector<RowValue>& values, std::size_t point_step)
{
  readLines (text, piece, [&] (const char* first, const char* last) {
    const std::size_t at = piece.data.size ();
    std::size_t count = 0;
    std::string problem;
    const bool numbers = forEachToken (first, last, [&] (const char* token, const char* end) {
      double number;
      if (!tokenValue (token, end, number))
        return false;
      if (count < values.size () && problem.empty ())
      {
        if (count == 0)
          piece.data.resize (at + point_step, 0);
        const RowValue& value = values[count];
        if (!value.skipped && !storeValue (token, end, number, value, piece.data.data () + at))
          problem = "'" + std::string (token, end) + "' does not fit field " + value.field;
      }
      ++count;
      return true;
    });
    if (!numbers)
    {
      piece.error = "not a number";
      piece.data.resize (at);
      return false;
    }
    if (count == 0)
      return true;
    if (problem.empty () && count != values.size ())
      problem = std::to_string (count) + " numbers where a point has " + std::to_string (values.size ());
    piece.number_lines.push_back (piece.lines);
    if (problem.empty ())
      piece.problem.push_back (0);
    else
    {
      piece.data.resize (at);
      piece.problems.push_back (std::move (problem));
      piece.problem.push_back (static_cast<std::uint32_t> (piece.problems.size ()));
    }
    return true;
  });
}

} // namespace

std::string
readAsciiRows (std::istream& in, std::uintmax_t bytes, const std::vector<RowValue>& values, std::size_t point_step,
               std::size_t rows, bool more_follow, std::vector<std::uint8_t>& data, std::size_t window_bytes,
               std::size_t chunk_bytes)
{
  std::size_t lines = 0, read = 0; // lines so far, rows so far
  std::string error;
  const auto lineName = [&] (std::size_t line) { return "data line " + std::to_string (lines + line + 1) + ": "; };
  readInWindows (in, bytes, window_bytes, [&] (const char* first, const char* last, double) {
    const std::vector<Piece> pieces =
        readPieces<Piece> (std::string_view (first, std::size_t (last - first)), chunk_bytes,
                           [&] (std::string_view text, Piece& piece) { readPiece (text, piece, values, point_step); });
    for (const Piece& piece : pieces)
    {
      // The piece's rows, in order, up to the last one wanted; a line with numbers after it is
      // another element's, or one too many.
      std::size_t from = 0; // bytes of piece.data taken
      for (std::size_t k = 0; k < piece.number_lines.size (); ++k)
      {
        if (read == rows && more_follow)
          break;
        if (read == rows)
          error = lineName (piece.number_lines[k]) + "more points than the " + std::to_string (rows) + " declared";
        else if (piece.problem[k] != 0)
          error = lineName (piece.number_lines[k]) + piece.problems[piece.problem[k] - 1];
        if (!error.empty ())
          return false;
        std::memcpy (data.data () + read * point_step, piece.data.data () + from, point_step);
        from += point_step;
        ++read;
      }
      if (piece.error_line != NO_LINE)
      {
        error = lineName (piece.error_line) + piece.error;
        return false;
      }
      lines += piece.lines;
    }
    return true;
  });
  if (error.empty () && read < rows)
    error = std::to_string (read) + " points where " + std::to_string (rows) + " are declared";
  return error;
}

} // namespace pcl_wrap::apps
