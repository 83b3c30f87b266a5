// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "pcl_file_checks.h"

#include "ply_ascii.h"
#include "point_file.h"
#include "text_pieces.h"

#include <pcl/common/io.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <vector>

namespace pcl_wrap::apps
{
namespace
{

/** PCL's PCD reader goes on parsing header lines after DATA, skipping blank lines and comments,
  * until a line that is no keyword: binary data that starts with one (found by fuzzing) would
  * redefine the fields after they were checked. Does the data from \a in on start so? */
bool
dataReadsAsHeader (std::ifstream& in)
{
  static const char* const KEYWORDS[] = {"VERSION", "FIELDS", "COLUMNS", "SIZE", "TYPE", "COUNT",
                                         "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
  std::string line;
  while (std::getline (in, line))
  {
    if (line.empty ())
      continue;
    std::istringstream words (line);
    std::string first;
    if (!(words >> first))
      return false; // PCL stops at a line of blanks
    if (first[0] == '#')
      continue;
    for (const char* keyword : KEYWORDS)
      if (first.compare (0, std::strlen (keyword), keyword) == 0)
        return true;
    return false;
  }
  return false;
}

} // namespace

void
checkPcdFile (const std::string& path)
{
  const auto bad = [&] (const std::string& what) { throw FileError (path + ": malformed PCD file: " + what); };
  std::ifstream in (path, std::ios::binary);
  std::vector<std::vector<std::string>> lines; // keyword and values, comments skipped
  std::string line;
  while (std::getline (in, line) && line.size () < 65536)
  {
    std::istringstream words (line);
    std::vector<std::string> tokens;
    for (std::string word; words >> word;)
      tokens.push_back (word);
    if (tokens.empty ())
      bad ("blank line in the header"); // PCL's reader crashes on one (found by fuzzing)
    if (tokens[0][0] == '#')
      continue;
    lines.push_back (tokens);
    if (tokens[0] == "DATA")
      break;
  }
  const std::vector<std::string> order = {"VERSION", "FIELDS", "SIZE",      "TYPE",   "COUNT",
                                          "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
  std::map<std::string, std::vector<std::string>> header;
  std::size_t next = 0;
  for (const auto& tokens : lines)
  {
    while (next < order.size () && order[next] != tokens[0])
      ++next;
    if (next == order.size ())
      bad ("unexpected or misplaced header line '" + tokens[0] + "'");
    header[tokens[0]] = {tokens.begin () + 1, tokens.end ()};
    ++next;
  }
  for (const char* required : {"FIELDS", "SIZE", "TYPE", "WIDTH", "HEIGHT", "POINTS", "DATA"})
    if (!header.count (required))
      bad (std::string ("no ") + required + " line");
  const auto number = [&] (const std::string& text, unsigned long max) {
    char* end = nullptr;
    errno = 0;
    const unsigned long v = std::strtoul (text.c_str (), &end, 10);
    if (text.empty () || text[0] == '-' || *end != '\0' || errno != 0 || v > max)
      bad ("bad number '" + text + "'");
    return v;
  };
  const auto& fields = header["FIELDS"];
  const std::size_t n = fields.size ();
  if (n == 0 || n > 1024 || header["SIZE"].size () != n || header["TYPE"].size () != n ||
      (header.count ("COUNT") && header["COUNT"].size () != n))
    bad ("FIELDS, SIZE, TYPE and COUNT differ in length");
  std::uint64_t point_size = 0, values = 0; // bytes and numbers a point
  for (std::size_t i = 0; i < n; ++i)
  {
    const unsigned long size = number (header["SIZE"][i], 8);
    const std::string& type = header["TYPE"][i];
    const unsigned long count = header.count ("COUNT") ? number (header["COUNT"][i], 1u << 20) : 1;
    if ((size != 1 && size != 2 && size != 4 && size != 8) || (type != "I" && type != "U" && type != "F") ||
        (type == "F" && size < 4) || count == 0)
      bad ("field " + fields[i] + " has a bad SIZE, TYPE or COUNT");
    point_size += size * count;
    values += count;
  }
  if (header["WIDTH"].size () != 1 || header["HEIGHT"].size () != 1 || header["POINTS"].size () != 1 ||
      header["DATA"].size () != 1)
    bad ("WIDTH, HEIGHT, POINTS and DATA take one value");
  const std::uint64_t points =
      std::uint64_t (number (header["WIDTH"][0], 0xffffffffUL)) * number (header["HEIGHT"][0], 0xffffffffUL);
  if (points != number (header["POINTS"][0], ~0ul))
    bad ("POINTS is not WIDTH x HEIGHT");
  const std::string& data = header["DATA"][0];
  const std::uint64_t start = static_cast<std::uint64_t> (in.tellg ());
  if (dataReadsAsHeader (in))
    bad ("the data starts with a header keyword, which PCL's reader would parse as a header line");
  in.clear ();
  in.seekg (0, std::ios::end);
  const std::uint64_t available = static_cast<std::uint64_t> (in.tellg ()) - start;
  if (data == "binary")
  {
    if (points > available / point_size)
      bad ("binary data shorter than " + std::to_string (points) + " points");
  }
  else if (data == "binary_compressed")
  {
    std::uint32_t sizes[2] = {0, 0}; // compressed, uncompressed
    in.seekg (std::streamoff (start));
    if (!in.read (reinterpret_cast<char*> (sizes), sizeof (sizes)) || sizes[0] > available - 8 ||
        points > 0xffffffffULL / point_size || std::uint64_t (sizes[1]) != points * point_size)
      bad ("compressed data does not match its header");
  }
  else if (data == "ascii")
  {
    // Its tokens are checked as they are read (readPcdAsciiData()); PCL's header reader sizes the
    // cloud before, and a number takes two bytes at least (a digit and a space or line end).
    if (points > (available + 1) / (2 * values))
      bad ("ASCII data shorter than " + std::to_string (points) + " points");
  }
  else
    bad ("unknown DATA '" + data + "'");
}

PlyHeaderCheck
checkPlyHeader (const std::string& path)
{
  const auto bad = [&] (const std::string& what) { throw FileError (path + ": malformed PLY file: " + what); };
  std::ifstream in (path, std::ios::binary);
  std::string line, format;
  std::vector<std::pair<std::uint64_t, std::uint64_t>> elements; // count, least bytes per item
  bool vertex = false;                                           // in the vertex element
  // Where the vertex's uchar colours are: none yet, after red, after green, after blue.
  enum class Colour
  {
    NONE,
    RED,
    GREEN,
    BLUE
  } colour = Colour::NONE;
  // PCL's reader makes a uchar red a packed "rgb" field, writes it at blue and moves on only there:
  // anything between red and blue, a second red, or a colour without red before it is misplaced or
  // written past the point (an assertion fails; found by fuzzing); alpha before blue is lost.
  const auto bad_colours = [&] { bad ("vertex colours not as red, green, blue in a row, then alpha"); };
  const auto red_without_blue = [&] { return colour == Colour::RED || colour == Colour::GREEN; };
  // The cloud's size as PCL's reader sets it: obj_info's num_cols and num_rows, else the vertices.
  std::uint32_t width = 0, height = 0;
  std::uint64_t vertices = 0;
  std::optional<std::uint64_t> range_grid; // its cells
  int vertex_elements = 0;
  // PCL's reader takes the fourth byte for the magic's end: a '\r' there makes it end header lines at
  // '\r' and skip the byte after each. Lines that end in "\r\n" alone read the same either way.
  if (!std::getline (in, line) || line.compare (0, 3, "ply") != 0 ||
      line.find_first_not_of (" \t\r", 3) != std::string::npos)
    bad ("no ply magic");
  const bool cr = line.size () > 3 && line[3] == '\r';
  while (std::getline (in, line) && line.substr (0, 10) != "end_header")
  {
    if (cr && (line.empty () || line.find ('\r') != line.size () - 1))
      bad ("a header line not ended by \"\\r\\n\" where the first one is");
    std::istringstream words (line);
    std::string keyword;
    words >> keyword;
    if (keyword == "format")
      words >> format;
    else if (keyword == "element")
    {
      std::string name;
      double count = -1;
      if (!(words >> name >> count) || count < 0 || count != std::floor (count) || count > 1e15)
        bad ("bad element line");
      if (red_without_blue ())
        bad_colours ();
      elements.emplace_back (static_cast<std::uint64_t> (count), 0);
      vertex = name == "vertex";
      if (vertex)
      {
        if (++vertex_elements > 1 || count > 0xffffffffu)
          bad ("a second vertex element, or more than 2^32 - 1 vertices");
        vertices = static_cast<std::uint64_t> (count);
        if (width == 0 || height == 0)
        {
          width = static_cast<std::uint32_t> (vertices);
          height = 1;
        }
      }
      if (name == "range_grid")
        range_grid = static_cast<std::uint64_t> (count);
    }
    else if (keyword == "obj_info")
    {
      // PCL's reader splits the line at blanks and tabs, fails an assertion unless its first word
      // starts with "obj_info", and reads num_cols and num_rows with atoi.
      if (line.compare (0, 8, "obj_info") != 0)
        bad ("an obj_info line that does not start with obj_info");
      std::vector<std::string> parts;
      const std::string text = cr ? line.substr (0, line.size () - 1) : line;
      for (std::size_t at = 0; (at = text.find_first_not_of (" \t", at)) != std::string::npos;)
      {
        const std::size_t end = std::min (text.find_first_of (" \t", at), text.size ());
        parts.push_back (text.substr (at, end - at));
        at = end;
      }
      if (parts.size () >= 3 && (parts[1] == "num_cols" || parts[1] == "num_rows"))
      {
        const auto value = static_cast<std::uint32_t> (static_cast<int> (std::strtol (parts[2].c_str (), nullptr, 10)));
        (parts[1] == "num_cols" ? width : height) = value;
      }
    }
    else if (keyword == "property")
    {
      std::string type;
      words >> type;
      const bool list = type == "list";
      if (list)
        words >> type; // the item count's type: the least a list takes
      const std::uint8_t field_type = plyFieldType (type);
      if (elements.empty () || field_type == 0)
        bad ("bad property line");
      // PCL's reader sizes a vertex's list by the first vertex's and places the fields after it as
      // if it held one item: a longer list later writes past the point (an assertion fails; found
      // by fuzzing), and any list longer than one misplaces what follows it.
      if (vertex && list)
        bad ("a list property in the vertex element");
      std::string name;
      words >> name;
      if (vertex)
      {
        const bool byte = field_type == pcl::PCLPointField::UINT8;
        const bool is_red = byte && (name == "red" || name == "diffuse_red");
        const bool is_green = byte && (name == "green" || name == "diffuse_green");
        const bool is_blue = byte && (name == "blue" || name == "diffuse_blue");
        if ((is_red && colour != Colour::NONE) || (is_green && colour != Colour::RED) ||
            (is_blue && colour != Colour::RED && colour != Colour::GREEN) ||
            (byte && name == "alpha" && colour != Colour::BLUE) ||
            (!is_red && !is_green && !is_blue && red_without_blue ()))
          bad_colours ();
        colour = is_red ? Colour::RED : is_green ? Colour::GREEN : is_blue ? Colour::BLUE : colour;
      }
      // ASCII: a digit and a space.
      elements.back ().second += format == "ascii" ? 2 : pcl::getFieldSize (field_type);
    }
  }
  if (!in)
    bad ("no end_header");
  if (red_without_blue ())
    bad_colours ();
  // PCL reads "end_header" only as a word of its own, and takes a line that merely starts with it
  // as more header (found by fuzzing: an element declared there was never checked here).
  if (line.find_first_not_of (" \t\r", 10) != std::string::npos || (cr && line.back () != '\r'))
    bad ("text after end_header on its line");
  if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
    bad ("unknown format '" + format + "'");
  const std::uint64_t start = static_cast<std::uint64_t> (in.tellg ());
  in.seekg (0, std::ios::end);
  std::uint64_t available = static_cast<std::uint64_t> (in.tellg ()) - start;
  for (const auto& [count, least] : elements)
  {
    if (least == 0 && count > 0) // PCL's reader loops over its items all the same (found by fuzzing)
      bad ("an element with items but no properties");
    if (least > 0 && count > available / least)
      bad ("the header declares more data than the file holds");
    available -= count * least;
  }
  PlyHeaderCheck check;
  check.ascii_start = format == "ascii" ? std::optional<std::uint64_t> (start) : std::nullopt;
  // PCL's reader sizes the cloud as num_cols x num_rows and writes the vertices into it: fewer
  // places fail an assertion, more leave points of zeros after the vertices
  // (PCL's own ASCII writer declares fewer vertices than places for a cloud with NaN points). A
  // range grid then moves the vertices to its cells, one place each.
  const std::uint64_t places = std::uint64_t (width) * height;
  check.points = range_grid.value_or (vertices);
  if (vertex_elements == 1 && (places != check.points || vertices > places))
    check.size_problem = "obj_info's num_cols x num_rows is " + std::to_string (places) + " points, the " +
                         (range_grid ? "range grid " : "vertex element ") + std::to_string (check.points);
  return check;
}

void
checkPlyAsciiData (const std::string& path, std::uint64_t start)
{
  std::ifstream in (path, std::ios::binary);
  in.seekg (0, std::ios::end);
  const auto end = static_cast<std::uint64_t> (in.tellg ());
  in.seekg (std::streamoff (start));
  const std::size_t line = firstLineNotNumbers (in, end - start);
  if (line != NO_LINE)
    throw FileError (path + ": malformed PLY file: data line " + std::to_string (line + 1) + ": not a number");
}

} // namespace pcl_wrap::apps
