// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "text_pieces.h"

#include "text_line.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <string>

namespace pcl_wrap::apps
{

// A plain decimal is read with std::from_chars, which rounds correctly as strtod does and is
// several times faster; anything else (a sign '+', hexadecimal, inf, nan, out of range, a byte no
// number has) is handed to parseNumbers() itself.
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

bool
appendNumbers (const char* first, const char* last, std::vector<double>& out, std::size_t& count)
{
  const std::size_t before = out.size ();
  const bool numbers = forEachToken (first, last, [&] (const char* token, const char* end) {
    double value;
    if (!tokenValue (token, end, value))
      return false;
    out.push_back (value);
    return true;
  });
  if (!numbers)
    out.resize (before);
  count = out.size () - before;
  return numbers;
}

std::vector<std::pair<std::size_t, std::size_t>>
wholeLinePieces (std::string_view text, std::size_t chunk_bytes)
{
  chunk_bytes = std::max<std::size_t> (chunk_bytes, 1);
  std::vector<std::pair<std::size_t, std::size_t>> pieces;
  for (std::size_t at = 0; at < text.size ();)
  {
    std::size_t end = std::min (text.size (), at + chunk_bytes);
    if (end < text.size ())
    {
      const std::size_t eol = text.find ('\n', end);
      end = eol == std::string_view::npos ? text.size () : eol + 1;
    }
    pieces.emplace_back (at, end);
    at = end;
  }
  return pieces;
}

std::size_t
firstLineNotNumbers (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes, std::size_t chunk_bytes)
{
  std::size_t lines = 0, failing = NO_LINE;
  readInWindows (in, bytes, window_bytes, [&] (const char* first, const char* last, double) {
    const std::vector<TextPiece> pieces =
        readPieces<TextPiece> (std::string_view (first, std::size_t (last - first)), chunk_bytes,
                               [] (std::string_view text, TextPiece& piece) {
                                 readLines (text, piece, [] (const char* line, const char* end) {
                                   return forEachToken (line, end, [] (const char* token, const char* token_end) {
                                     double value;
                                     return tokenValue (token, token_end, value);
                                   });
                                 });
                               });
    for (const TextPiece& piece : pieces)
    {
      if (piece.error_line != NO_LINE)
      {
        failing = lines + piece.error_line;
        return false;
      }
      lines += piece.lines;
    }
    return true;
  });
  return failing;
}

void
readInWindows (std::istream& in, std::uintmax_t bytes, std::size_t window_bytes,
               const std::function<bool (const char* first, const char* last, double share)>& parse)
{
  std::string window; // the text not parsed yet: a line's start, then what is read after it
  window_bytes = std::max<std::size_t> (window_bytes, 1);
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
    const double share = first && reading && bytes > whole ? double (whole) / double (bytes) : 0.0;
    if (!parse (window.data (), window.data () + whole, share))
      break;
    first = false;
    window.erase (0, whole);
  }
}

} // namespace pcl_wrap::apps
