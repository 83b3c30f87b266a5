// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "point_file.h"

#include "pcl_file_checks.h"
#include "text_line.h"
#include "xyz_text.h"

#include <pcl_wrap/point_field.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace pcl_wrap::apps
{
namespace
{

std::string
extensionOf (const std::string& path)
{
  const auto dot = path.find_last_of ('.');
  const auto slash = path.find_last_of ('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string ext = path.substr (dot);
  std::transform (ext.begin (), ext.end (), ext.begin (), [] (unsigned char c) { return std::tolower (c); });
  return ext;
}

[[noreturn]] void
fail (const std::string& path, const std::string& problem)
{
  throw FileError (path + ": " + problem);
}

std::ifstream
openText (const std::string& path)
{
  std::ifstream in (path);
  if (!in)
    fail (path, std::string ("cannot open: ") + std::strerror (errno));
  return in;
}

/** Normals when every row is of unit length (within a written file's rounding), colours when
  * every value is a whole number from 0 to 255; none of the two otherwise. */
enum class TripleKind
{
  normals,
  colours,
  other
};

TripleKind
kindOf (const std::vector<std::array<double, 3>>& rows)
{
  const bool unit = std::all_of (rows.begin (), rows.end (), [] (const std::array<double, 3>& r) {
    return std::abs (r[0] * r[0] + r[1] * r[1] + r[2] * r[2] - 1) < 1e-2;
  });
  const bool bytes = std::all_of (rows.begin (), rows.end (), [] (const std::array<double, 3>& r) {
    return std::all_of (r.begin (), r.end (), [] (double c) { return c >= 0 && c <= 255 && c == std::floor (c); });
  });
  return unit ? TripleKind::normals : bytes ? TripleKind::colours : TripleKind::other;
}

/** Columns from \a first of \a columns (a list per column) as normals or colours when \a kind
  * says so. */
void
takeTriple (const std::vector<std::vector<double>>& columns, std::size_t first, TripleKind kind, PointAttributes& out)
{
  const std::size_t n = columns[first].size ();
  for (std::size_t i = 0; i < n; ++i)
    if (kind == TripleKind::normals)
      out.normals.push_back ({float (columns[first][i]), float (columns[first + 1][i]), float (columns[first + 2][i])});
    else
      out.colours.push_back ({std::uint8_t (columns[first][i]), std::uint8_t (columns[first + 1][i]),
                              std::uint8_t (columns[first + 2][i]), 255});
}

PointFile
readXyz (const std::string& path, bool weights_column)
{
  std::ifstream in = openText (path);
  std::error_code unknown; // not a regular file: no room is made ahead
  const std::uintmax_t bytes = std::filesystem::file_size (path, unknown);
  XyzTable table = readXyzStream (in, unknown ? 0 : bytes);
  if (!table.error.empty ())
    fail (path, table.error);
  PointFile file;
  const std::size_t columns = table.columns;
  const std::size_t rows = columns == 0 ? 0 : table.values.size () / columns;
  file.points.resize (rows);
  std::vector<std::vector<double>> extra (columns < 3 ? 0 : columns - 3, std::vector<double> (rows));
  for (std::size_t i = 0; i < rows; ++i)
  {
    const double* row = &table.values[i * columns];
    file.points[i] = {row[0], row[1], row[2]};
    for (std::size_t c = 3; c < columns; ++c)
      extra[c - 3][i] = row[c];
  }
  table = {};
  if (weights_column && columns < 4 && !file.points.empty ())
    fail (path, "--weights-column: the lines have no 4th column");
  std::size_t first = 0; // the first column not taken yet
  if (weights_column && !extra.empty ())
  {
    file.weights = extra[0];
    file.attributes.scalars.push_back ({"weight", 8, extra[0]});
    first = 1;
  }
  const std::size_t left = extra.size () - first;
  if (left == 3 || left == 6)
  {
    const auto triple = [&] (std::size_t at) {
      std::vector<std::array<double, 3>> rows (file.points.size ());
      for (std::size_t i = 0; i < rows.size (); ++i)
        rows[i] = {extra[at][i], extra[at + 1][i], extra[at + 2][i]};
      return kindOf (rows);
    };
    const TripleKind a = triple (first), b = left == 6 ? triple (first + 3) : TripleKind::other;
    const bool taken = left == 3 ? a != TripleKind::other : a != TripleKind::other && b != TripleKind::other && a != b;
    if (taken)
    {
      takeTriple (extra, first, a, file.attributes);
      if (left == 6)
        takeTriple (extra, first + 3, b, file.attributes);
      first += left;
    }
  }
  for (std::size_t c = first; c < extra.size (); ++c)
    file.attributes.scalars.push_back ({"field" + std::to_string (c + 4), 8, std::move (extra[c])});
  return file;
}

/** Colours of a file as bytes: components above 1 say they are 0 to 255 already, else 0 to 1. */
std::array<std::uint8_t, 4>
colourOf (const double* rgba, bool has_alpha, bool bytes)
{
  std::array<std::uint8_t, 4> out{0, 0, 0, 255};
  for (int k = 0; k < (has_alpha ? 4 : 3); ++k)
  {
    const double c = std::clamp (bytes ? rgba[k] : rgba[k] * 255.0, 0.0, 255.0);
    out[k] = static_cast<std::uint8_t> (std::lround (c));
  }
  return out;
}

PointFile
readOff (const std::string& path)
{
  std::ifstream in = openText (path);
  std::string line;
  std::vector<double> numbers;
  std::size_t number = 0;
  // The next line with content, or failure at the end of the file.
  const auto next = [&] (const char* what) {
    while (std::getline (in, line))
    {
      ++number;
      if (!parseNumbers (line, numbers))
        fail (path, "line " + std::to_string (number) + ": not a number in " + what);
      if (!numbers.empty ())
        return;
    }
    fail (path, std::string ("ends before ") + what);
  };
  std::string header;
  while (header.empty () && std::getline (in, line))
  {
    ++number;
    std::istringstream (line.substr (0, line.find ('#'))) >> header;
  }
  if (header.size () < 3 || header.compare (header.size () - 3, 3, "OFF") != 0)
    fail (path, "not an OFF file (no OFF header)");
  // [ST][C][N][4][n]OFF: a vertex line is x y z [nx ny nz] [r g b [a]] [s t].
  const std::string prefix = header.substr (0, header.size () - 3);
  const bool with_normals = prefix.find ('N') != std::string::npos;
  const bool with_colours = prefix.find ('C') != std::string::npos;
  // The counts may follow the keyword on the header line.
  std::istringstream rest (line.substr (line.find ("OFF") + 3));
  double count = 0;
  if (!(rest >> count))
  {
    next ("the vertex count");
    count = numbers[0];
  }
  if (!(count >= 0 && count <= 4.0e9 && count == std::floor (count)))
    fail (path, "bad vertex count");
  PointFile file;
  const auto reserve = static_cast<std::size_t> (std::min (count, 1.0e7));
  file.points.reserve (reserve);
  std::vector<std::array<double, 4>> colours; // as written; bytes or fractions decided at the end
  bool has_alpha = true, bytes = false;
  for (std::size_t i = 0; i < static_cast<std::size_t> (count); ++i)
  {
    next ("all vertices are read");
    const std::size_t needed = 3 + (with_normals ? 3 : 0) + (with_colours ? 3 : 0);
    if (numbers.size () < needed)
      fail (path, "line " + std::to_string (number) + ": a vertex needs " + std::to_string (needed) + " numbers");
    file.points.push_back ({numbers[0], numbers[1], numbers[2]});
    if (with_normals)
      file.attributes.normals.push_back ({float (numbers[3]), float (numbers[4]), float (numbers[5])});
    if (with_colours)
    {
      const double* c = numbers.data () + (with_normals ? 6 : 3);
      const bool alpha = numbers.size () >= needed + 1;
      has_alpha = has_alpha && alpha;
      colours.push_back ({c[0], c[1], c[2], alpha ? c[3] : 1.0});
      bytes = bytes || c[0] > 1 || c[1] > 1 || c[2] > 1;
    }
  }
  for (const auto& c : colours)
    file.attributes.colours.push_back (colourOf (c.data (), has_alpha, bytes));
  file.attributes.alpha = with_colours && has_alpha;
  return file;
}

PointFile
readObj (const std::string& path)
{
  std::ifstream in = openText (path);
  PointFile file;
  std::vector<std::array<double, 3>> colours;
  std::vector<std::array<float, 3>> normals;
  bool every_vertex_coloured = true;
  std::vector<double> numbers;
  std::string line;
  for (std::size_t number = 1; std::getline (in, line); ++number)
  {
    const std::size_t start = line.find_first_not_of (" \t");
    const std::size_t end = line.find_first_of (" \t", start);
    if (start == std::string::npos || end == std::string::npos)
      continue;
    const std::string keyword = line.substr (start, end - start);
    if (keyword == "vn")
    {
      if (!parseNumbers (line.substr (end), numbers) || numbers.size () != 3)
        fail (path, "line " + std::to_string (number) + ": a normal needs 3 numbers");
      normals.push_back ({float (numbers[0]), float (numbers[1]), float (numbers[2])});
      continue;
    }
    if (keyword != "v")
      continue;
    if (!parseNumbers (line.substr (end), numbers) || numbers.size () < 3 || numbers.size () > 7)
      fail (path, "line " + std::to_string (number) + ": a vertex needs 3 coordinates");
    file.points.push_back ({numbers[0], numbers[1], numbers[2]});
    every_vertex_coloured = every_vertex_coloured && numbers.size () == 6; // "v x y z r g b"
    if (every_vertex_coloured)
      colours.push_back ({numbers[3], numbers[4], numbers[5]});
  }
  if (every_vertex_coloured && !file.points.empty ())
  {
    bool bytes = false;
    for (const auto& c : colours)
      bytes = bytes || c[0] > 1 || c[1] > 1 || c[2] > 1;
    for (const auto& c : colours)
      file.attributes.colours.push_back (colourOf (c.data (), false, bytes));
  }
  if (normals.size () == file.points.size ())
    file.attributes.normals = std::move (normals);
  return file;
}

/** x, y, z (float or double) of every point of a PCL cloud, and the weight field's values. */
PointFile
pointsOf (const pcl::PCLPointCloud2& cloud, const std::string& path, const std::string& weight_field)
{
  for (const char* axis : {"x", "y", "z"})
  {
    const auto field = std::find_if (cloud.fields.begin (), cloud.fields.end (),
                                     [&] (const pcl::PCLPointField& f) { return f.name == axis; });
    if (field == cloud.fields.end () ||
        (field->datatype != pcl::PCLPointField::FLOAT32 && field->datatype != pcl::PCLPointField::FLOAT64))
      fail (path, std::string ("no float or double field ") + axis);
  }
  try
  {
    const std::vector<double> x = readFieldValues (cloud, "x"), y = readFieldValues (cloud, "y"),
                              z = readFieldValues (cloud, "z");
    PointFile file;
    file.points.resize (x.size ());
    for (std::size_t i = 0; i < x.size (); ++i)
      file.points[i] = {x[i], y[i], z[i]};
    if (!weight_field.empty ())
      file.weights = readFieldValues (cloud, weight_field);
    file.attributes = attributesOf (cloud);
    return file;
  }
  catch (const std::invalid_argument& e)
  {
    fail (path, e.what ());
  }
}

PointFile
readWithPcl (const std::string& path, bool pcd, const std::string& weight_field)
{
  if (!std::ifstream (path))
    fail (path, std::string ("cannot open: ") + std::strerror (errno));
  // PCL's readers report on the console themselves; the caller prints one line instead.
  const auto verbosity = pcl::console::getVerbosityLevel ();
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero ();
  Eigen::Quaternionf orientation;
  int status = -1;
  try
  {
    if (pcd)
      checkPcdFile (path);
    else
      checkPlyFile (path);
    status = pcd ? pcl::io::loadPCDFile (path, cloud, origin, orientation) : pcl::io::loadPLYFile (path, cloud);
  }
  catch (const FileError&)
  {
    pcl::console::setVerbosityLevel (verbosity);
    throw;
  }
  catch (const std::exception& e)
  {
    pcl::console::setVerbosityLevel (verbosity);
    fail (path, std::string ("malformed ") + (pcd ? "PCD" : "PLY") + " file: " + e.what ());
  }
  pcl::console::setVerbosityLevel (verbosity);
  if (status < 0)
    fail (path, std::string ("malformed ") + (pcd ? "PCD" : "PLY") + " file");
  PointFile file = pointsOf (cloud, path, weight_field);
  if (pcd && (cloud.height > 1 || origin.head<3> ().squaredNorm () > 0))
    file.viewpoint = Point3{origin[0], origin[1], origin[2]};
  return file;
}

} // namespace

PointFile
readPointFile (const std::string& path, const std::string& weight_field, bool weights_column)
{
  const std::string ext = extensionOf (path);
  const bool pcl_format = ext == ".pcd" || ext == ".ply";
  const bool text = ext == ".xyz" || ext == ".txt";
  if (!weight_field.empty () && !pcl_format)
    fail (path, "only .pcd and .ply files have fields to take weights from (a .xyz file's 4th column is, with "
                "--weights-column)");
  if (weights_column && !text)
    fail (path, "only .xyz and .txt files have a weights column (a .pcd or .ply file names its field, with "
                "--weight-field)");
  PointFile file;
  if (pcl_format)
    file = readWithPcl (path, ext == ".pcd", weight_field);
  else if (text)
    file = readXyz (path, weights_column);
  else if (ext == ".off")
    file = readOff (path);
  else if (ext == ".obj")
    file = readObj (path);
  else
    fail (path, "unknown input format '" + ext + "' (expected .pcd, .ply, .xyz, .txt, .off or .obj)");
  if (file.points.empty ())
    fail (path, "no points");
  return file;
}

std::vector<Point3>
readPoints (const std::string& path)
{
  return readPointFile (path).points;
}

} // namespace pcl_wrap::apps
