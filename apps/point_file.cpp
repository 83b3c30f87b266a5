// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "point_file.h"

#include "obj_text.h"
#include "off_text.h"
#include "pcd_ascii.h"
#include "ply_ascii.h"
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

/** The length of the file at \a path, or 0 where it is not known (not a regular file). */
std::uintmax_t
knownLength (const std::string& path)
{
  std::error_code unknown;
  const std::uintmax_t bytes = std::filesystem::file_size (path, unknown);
  return unknown ? 0 : bytes;
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
  XyzTable table = readXyzStream (in, knownLength (path));
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
  const OffVertices read = readOffStream (in);
  if (!read.error.empty ())
    fail (path, read.error);
  PointFile file;
  const std::size_t n = read.begin.size () - 1;
  file.points.resize (n);
  std::vector<std::array<double, 4>> colours; // as written; bytes or fractions decided at the end
  bool has_alpha = true, bytes = false;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double* numbers = &read.values[read.begin[i]];
    file.points[i] = {numbers[0], numbers[1], numbers[2]};
    if (read.normals)
      file.attributes.normals.push_back ({float (numbers[3]), float (numbers[4]), float (numbers[5])});
    if (read.colours)
    {
      const double* c = numbers + (read.normals ? 6 : 3);
      const bool alpha = read.begin[i + 1] - read.begin[i] >= read.needed + 1;
      has_alpha = has_alpha && alpha;
      colours.push_back ({c[0], c[1], c[2], alpha ? c[3] : 1.0});
      bytes = bytes || c[0] > 1 || c[1] > 1 || c[2] > 1;
    }
  }
  for (const auto& c : colours)
    file.attributes.colours.push_back (colourOf (c.data (), has_alpha, bytes));
  file.attributes.alpha = read.colours && has_alpha;
  return file;
}

PointFile
readObj (const std::string& path)
{
  std::ifstream in = openText (path);
  ObjVertices read = readObjStream (in, knownLength (path));
  if (!read.error.empty ())
    fail (path, read.error);
  PointFile file;
  file.points.resize (read.points.size () / 3);
  for (std::size_t i = 0; i < file.points.size (); ++i)
    file.points[i] = {read.points[3 * i], read.points[3 * i + 1], read.points[3 * i + 2]};
  if (read.every_vertex_coloured && !file.points.empty ())
  {
    const bool bytes_given = std::any_of (read.colours.begin (), read.colours.end (), [] (double c) { return c > 1; });
    for (std::size_t i = 0; i < file.points.size (); ++i)
      file.attributes.colours.push_back (colourOf (&read.colours[3 * i], false, bytes_given));
  }
  if (read.normals.size () == read.points.size ())
    for (std::size_t i = 0; i < file.points.size (); ++i)
      file.attributes.normals.push_back ({read.normals[3 * i], read.normals[3 * i + 1], read.normals[3 * i + 2]});
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

/** A PCD file into \a cloud: the header by PCL's reader, once checked; ASCII data by
  * readPcdAsciiData() on all threads, binary data by PCL's reader. PCL's status. */
int
readPcd (const std::string& path, pcl::PCLPointCloud2& cloud, Eigen::Vector4f& origin, Eigen::Quaternionf& orientation)
{
  checkPcdFile (path);
  pcl::PCDReader reader;
  int version = 0, data_type = 0;
  unsigned int data_start = 0;
  const int status = reader.readHeader (path, cloud, origin, orientation, version, data_type, data_start);
  if (status < 0 || data_type != 0)
    return status < 0 ? status : reader.read (path, cloud, origin, orientation, version);
  std::ifstream in (path, std::ios::binary);
  in.seekg (std::streamoff (data_start));
  const std::uintmax_t length = knownLength (path);
  const std::string error = readPcdAsciiData (in, length > data_start ? length - data_start : 0, cloud);
  if (!error.empty ())
    fail (path, "malformed PCD file: " + error);
  return 0;
}

/** A PLY file into \a cloud: the vertices of an ASCII file with a plain header
  * (plainAsciiPlyLayout()) on all threads, laid out as PCL's reader lays them out; any other file
  * by PCL's reader, once checked. PCL's status. */
int
readPly (const std::string& path, pcl::PCLPointCloud2& cloud)
{
  const PlyHeaderCheck header = checkPlyHeader (path);
  if (const std::optional<std::uint64_t> ascii_start = header.ascii_start)
  {
    std::ifstream in (path, std::ios::binary);
    if (std::optional<PlyVertexLayout> layout = plainAsciiPlyLayout (in))
    {
      cloud = std::move (layout->cloud);
      const std::uintmax_t length = knownLength (path);
      const std::string error = readAsciiRows (in, length > layout->data_start ? length - layout->data_start : 0,
                                               layout->values, cloud.point_step, cloud.width, true, cloud.data);
      if (!error.empty ())
        fail (path, "malformed PLY file: " + error);
      return 0;
    }
    checkPlyAsciiData (path, *ascii_start);
  }
  if (!header.size_problem.empty ())
    fail (path, "malformed PLY file: " + header.size_problem);
  const int status = pcl::io::loadPLYFile (path, cloud);
  // A camera element's viewport, read with the data, resizes the cloud too.
  const std::uint64_t read = std::uint64_t (cloud.width) * cloud.height;
  if (status >= 0 && read != header.points)
    fail (path, "malformed PLY file: a camera's viewport or obj_info says " + std::to_string (read) +
                    " points, not the " + std::to_string (header.points) + " it holds");
  return status;
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
      status = readPcd (path, cloud, origin, orientation);
    else
      status = readPly (path, cloud);
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
