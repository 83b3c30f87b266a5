// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "pcd_ascii.h"

#include "text_pieces.h"

#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

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

/** One value of a data line: the field it belongs to and where it goes in a point. */
struct Column
{
  const pcl::PCLPointField* field;
  std::uint32_t offset;
  bool padding; ///< a field named "_", skipped
};

std::vector<Column>
columnsOf (const pcl::PCLPointCloud2& cloud)
{
  std::vector<Column> columns;
  for (const pcl::PCLPointField& f : cloud.fields)
    for (std::uint32_t c = 0; c < f.count; ++c)
      columns.push_back (
          {&f, f.offset + c * static_cast<std::uint32_t> (pcl::getFieldSize (f.datatype)), f.name == "_"});
  return columns;
}

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

/** The whole number of type T that the number token [first, last) is, if it is one that T holds. */
template <class T>
bool
wholeNumber (const char* first, const char* last, T& out)
{
  const auto [end, ec] = std::from_chars (first, last, out);
  if (ec == std::errc () && end == last)
    return true;
  double value;
  if (!tokenValue (first, last, value) || value != std::floor (value))
    return false;
  // T's range, as powers of two that a double holds exactly.
  constexpr int bits = std::numeric_limits<T>::digits;
  const double below = std::numeric_limits<T>::is_signed ? -std::ldexp (1.0, bits) : 0.0;
  if (!(value >= below && value < std::ldexp (1.0, bits)))
    return false;
  out = static_cast<T> (value);
  return true;
}

template <class T>
bool
storeWhole (const char* first, const char* last, std::uint8_t* at)
{
  T value;
  if (!wholeNumber (first, last, value))
    return false;
  std::memcpy (at, &value, sizeof value);
  return true;
}

/** Stores the number token [first, last) at \a point + the column's offset, as its field's type;
  * false where it does not fit an integer field. */
bool
storeValue (const char* first, const char* last, const Column& column, std::uint8_t* point)
{
  std::uint8_t* at = point + column.offset;
  switch (column.field->datatype)
  {
  case pcl::PCLPointField::INT8: return storeWhole<std::int8_t> (first, last, at);
  case pcl::PCLPointField::UINT8: return storeWhole<std::uint8_t> (first, last, at);
  case pcl::PCLPointField::INT16: return storeWhole<std::int16_t> (first, last, at);
  case pcl::PCLPointField::UINT16: return storeWhole<std::uint16_t> (first, last, at);
  case pcl::PCLPointField::INT32: return storeWhole<std::int32_t> (first, last, at);
  case pcl::PCLPointField::UINT32: return storeWhole<std::uint32_t> (first, last, at);
  case pcl::PCLPointField::INT64: return storeWhole<std::int64_t> (first, last, at);
  case pcl::PCLPointField::UINT64: return storeWhole<std::uint64_t> (first, last, at);
  case pcl::PCLPointField::BOOL:
  {
    std::uint8_t value;
    if (!wholeNumber (first, last, value) || value > 1)
      return false;
    *at = value;
    return true;
  }
  case pcl::PCLPointField::FLOAT32:
  {
    double value;
    tokenValue (first, last, value);
    const float single = toFloat (value);
    std::memcpy (at, &single, sizeof single);
    return true;
  }
  case pcl::PCLPointField::FLOAT64:
  {
    double value;
    tokenValue (first, last, value);
    std::memcpy (at, &value, sizeof value);
    return true;
  }
  default: return false;
  }
}

/** One task's whole lines: their points, as in the cloud's data. */
struct Piece : TextPiece
{
  std::vector<std::uint8_t> data;
  std::string error; ///< the problem of its error_line
};

void
readPiece (std::string_view text, Piece& piece, const std::vector<Column>& columns, std::size_t point_step)
{
  readLines (text, piece, [&] (const char* first, const char* last) {
    const std::size_t at = piece.data.size ();
    std::size_t count = 0;
    const bool numbers = forEachToken (first, last, [&] (const char* token, const char* end) {
      double value;
      if (!tokenValue (token, end, value))
      {
        piece.error = "not a number";
        return false;
      }
      if (count < columns.size ())
      {
        if (count == 0)
          piece.data.resize (at + point_step, 0);
        const Column& column = columns[count];
        if (!column.padding && !storeValue (token, end, column, piece.data.data () + at))
        {
          piece.error = "'" + std::string (token, end) + "' does not fit field " + column.field->name;
          return false;
        }
      }
      ++count;
      return true;
    });
    if (numbers && count != 0 && count != columns.size ())
      piece.error = std::to_string (count) + " numbers where the fields take " + std::to_string (columns.size ());
    if (!piece.error.empty ())
    {
      piece.data.resize (at);
      return false;
    }
    return true;
  });
}

} // namespace

std::string
readPcdAsciiData (std::istream& in, std::uintmax_t bytes, pcl::PCLPointCloud2& cloud, std::size_t window_bytes,
                  std::size_t chunk_bytes)
{
  const std::vector<Column> columns = columnsOf (cloud);
  const std::size_t point_step = cloud.point_step;
  std::size_t lines = 0, written = 0;
  std::string error;
  readInWindows (in, bytes, window_bytes, [&] (const char* first, const char* last, double) {
    const std::vector<Piece> pieces =
        readPieces<Piece> (std::string_view (first, std::size_t (last - first)), chunk_bytes,
                           [&] (std::string_view text, Piece& piece) { readPiece (text, piece, columns, point_step); });
    for (const Piece& piece : pieces)
    {
      if (written + piece.data.size () > cloud.data.size ())
      {
        error = "more points than the header's " + std::to_string (cloud.width * std::uint64_t (cloud.height));
        return false;
      }
      if (!piece.data.empty ())
        std::memcpy (cloud.data.data () + written, piece.data.data (), piece.data.size ());
      written += piece.data.size ();
      if (piece.error_line != NO_LINE)
      {
        error = "data line " + std::to_string (lines + piece.error_line + 1) + ": " + piece.error;
        return false;
      }
      lines += piece.lines;
    }
    return true;
  });
  if (error.empty () && written != cloud.data.size ())
    error = std::to_string (point_step > 0 ? written / point_step : 0) + " points where the header declares " +
            std::to_string (cloud.width * std::uint64_t (cloud.height));
  cloud.is_dense = false; // not looked at: NaN values are allowed
  return error;
}

} // namespace pcl_wrap::apps
