// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "point_file.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
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

/** The whitespace-separated numbers of one line, after a '#' comment is cut off; false when a
  * token is not a number. "nan" and "inf" are numbers (such points are skipped, not rejected). */
bool
parseNumbers (const std::string& line, std::vector<double>& out)
{
  out.clear ();
  const std::string text = line.substr (0, line.find ('#'));
  std::istringstream tokens (text);
  std::string token;
  while (tokens >> token)
  {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod (token.c_str (), &end);
    if (end == token.c_str () || *end != '\0' || errno == ERANGE && std::abs (value) > 1.0)
      return false;
    out.push_back (value);
  }
  return true;
}

std::ifstream
openText (const std::string& path)
{
  std::ifstream in (path);
  if (!in)
    fail (path, std::string ("cannot open: ") + std::strerror (errno));
  return in;
}

std::vector<Point3>
readXyz (const std::string& path)
{
  std::ifstream in = openText (path);
  std::vector<Point3> points;
  std::vector<double> numbers;
  std::string line;
  std::size_t columns = 0;
  for (std::size_t number = 1; std::getline (in, line); ++number)
  {
    if (!parseNumbers (line, numbers))
      fail (path, "line " + std::to_string (number) + ": not a number");
    if (numbers.empty ())
      continue;
    if (numbers.size () != 3 && numbers.size () != 6)
      fail (path, "line " + std::to_string (number) + ": expected 3 numbers (x y z) or 6 (x y z nx ny nz), found " +
                      std::to_string (numbers.size ()));
    if (columns != 0 && numbers.size () != columns)
      fail (path, "line " + std::to_string (number) + ": " + std::to_string (numbers.size ()) +
                      " numbers where earlier lines have " + std::to_string (columns));
    columns = numbers.size ();
    points.push_back ({numbers[0], numbers[1], numbers[2]});
  }
  return points;
}

std::vector<Point3>
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
  std::vector<Point3> points;
  points.reserve (static_cast<std::size_t> (std::min (count, 1.0e7)));
  for (std::size_t i = 0; i < static_cast<std::size_t> (count); ++i)
  {
    next ("all vertices are read");
    if (numbers.size () < 3)
      fail (path, "line " + std::to_string (number) + ": a vertex needs 3 coordinates");
    points.push_back ({numbers[0], numbers[1], numbers[2]});
  }
  return points;
}

std::vector<Point3>
readObj (const std::string& path)
{
  std::ifstream in = openText (path);
  std::vector<Point3> points;
  std::vector<double> numbers;
  std::string line;
  for (std::size_t number = 1; std::getline (in, line); ++number)
  {
    std::size_t start = line.find_first_not_of (" \t");
    if (start == std::string::npos || line.compare (start, 2, "v ") != 0 && line.compare (start, 2, "v\t") != 0)
      continue;
    if (!parseNumbers (line.substr (start + 2), numbers) || numbers.size () < 3 || numbers.size () > 7)
      fail (path, "line " + std::to_string (number) + ": a vertex needs 3 coordinates");
    points.push_back ({numbers[0], numbers[1], numbers[2]});
  }
  return points;
}

/** x, y, z of every point of a PCL cloud with float or double coordinates. */
std::vector<Point3>
pointsOf (const pcl::PCLPointCloud2& cloud, const std::string& path)
{
  const pcl::PCLPointField* xyz[3] = {nullptr, nullptr, nullptr};
  for (const auto& field : cloud.fields)
    for (int a = 0; a < 3; ++a)
      if (field.name == std::string (1, "xyz"[a]))
        xyz[a] = &field;
  for (int a = 0; a < 3; ++a)
    if (!xyz[a] || (xyz[a]->datatype != pcl::PCLPointField::FLOAT32 && xyz[a]->datatype != pcl::PCLPointField::FLOAT64))
      fail (path, std::string ("no float or double field ") + "xyz"[a]);
    else if (xyz[a]->offset + (xyz[a]->datatype == pcl::PCLPointField::FLOAT64 ? 8u : 4u) > cloud.point_step)
      fail (path, "field offset beyond the point size");
  const std::size_t n = std::size_t (cloud.width) * cloud.height;
  if (n * cloud.point_step > cloud.data.size ())
    fail (path, "point data shorter than its header says");
  std::vector<Point3> points (n);
  for (std::size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
    {
      const std::uint8_t* at = &cloud.data[i * cloud.point_step + xyz[a]->offset];
      if (xyz[a]->datatype == pcl::PCLPointField::FLOAT64)
        std::memcpy (&points[i][a], at, sizeof (double));
      else
      {
        float f;
        std::memcpy (&f, at, sizeof (float));
        points[i][a] = f;
      }
    }
  return points;
}

/** PCL's PCD reader trusts the header and reads past the data of a malformed file: check the
  * layout the header declares against the file before handing it over. */
void
checkPcdLayout (const std::string& path)
{
  pcl::PCLPointCloud2 header;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0, data_type = 0;
  unsigned int data_index = 0;
  if (pcl::PCDReader ().readHeader (path, header, origin, orientation, version, data_type, data_index) < 0 ||
      header.fields.empty () || header.point_step == 0)
    fail (path, "malformed PCD file: bad header");
  std::ifstream in (path, std::ios::binary | std::ios::ate);
  const std::uint64_t size = static_cast<std::uint64_t> (in.tellg ());
  const std::uint64_t points = std::uint64_t (header.width) * header.height;
  for (const auto& field : header.fields)
    if (field.offset >= header.point_step)
      fail (path, "malformed PCD file: field " + field.name + " beyond the point size");
  if (data_index > size)
    fail (path, "malformed PCD file: no data");
  if (data_type == 1 && points * header.point_step > size - data_index)
    fail (path, "malformed PCD file: binary data shorter than " + std::to_string (points) + " points");
  if (data_type == 2)
  {
    std::uint32_t sizes[2] = {0, 0}; // compressed, uncompressed
    in.seekg (data_index);
    if (!in.read (reinterpret_cast<char*> (sizes), sizeof (sizes)) || sizes[0] > size - data_index - 8 ||
        std::uint64_t (sizes[1]) != points * header.point_step)
      fail (path, "malformed PCD file: compressed data does not match its header");
  }
}

std::vector<Point3>
readWithPcl (const std::string& path, bool pcd)
{
  if (!std::ifstream (path))
    fail (path, std::string ("cannot open: ") + std::strerror (errno));
  // PCL's readers report on the console themselves; the caller prints one line instead.
  const auto verbosity = pcl::console::getVerbosityLevel ();
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  pcl::PCLPointCloud2 cloud;
  int status = -1;
  try
  {
    if (pcd)
      checkPcdLayout (path);
    status = pcd ? pcl::io::loadPCDFile (path, cloud) : pcl::io::loadPLYFile (path, cloud);
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
  return pointsOf (cloud, path);
}

} // namespace

std::vector<Point3>
readPoints (const std::string& path)
{
  const std::string ext = extensionOf (path);
  std::vector<Point3> points;
  if (ext == ".pcd" || ext == ".ply")
    points = readWithPcl (path, ext == ".pcd");
  else if (ext == ".xyz" || ext == ".txt")
    points = readXyz (path);
  else if (ext == ".off")
    points = readOff (path);
  else if (ext == ".obj")
    points = readObj (path);
  else
    fail (path, "unknown input format '" + ext + "' (expected .pcd, .ply, .xyz, .txt, .off or .obj)");
  if (points.empty ())
    fail (path, "no points");
  return points;
}

} // namespace pcl_wrap::apps
