// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "point_file.h"

#include "pcl_file_checks.h"
#include "text_line.h"

#include <pcl_wrap/point_field.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
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

PointFile
readXyz (const std::string& path)
{
  std::ifstream in = openText (path);
  PointFile file;
  std::vector<double> numbers;
  std::string line;
  std::size_t columns = 0;
  for (std::size_t number = 1; std::getline (in, line); ++number)
  {
    if (!parseNumbers (line, numbers))
      fail (path, "line " + std::to_string (number) + ": not a number");
    if (numbers.empty ())
      continue;
    if (numbers.size () != 3 && numbers.size () != 4 && numbers.size () != 6)
      fail (path, "line " + std::to_string (number) + ": expected 3 numbers (x y z), 4 (x y z weight) or 6 " +
                      "(x y z nx ny nz), found " + std::to_string (numbers.size ()));
    if (columns != 0 && numbers.size () != columns)
      fail (path, "line " + std::to_string (number) + ": " + std::to_string (numbers.size ()) +
                      " numbers where earlier lines have " + std::to_string (columns));
    columns = numbers.size ();
    file.points.push_back ({numbers[0], numbers[1], numbers[2]});
    if (columns == 4)
      file.weights.push_back (numbers[3]);
  }
  return file;
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
readPointFile (const std::string& path, const std::string& weight_field)
{
  const std::string ext = extensionOf (path);
  const bool pcl_format = ext == ".pcd" || ext == ".ply";
  if (!weight_field.empty () && !pcl_format)
    fail (path, "only .pcd and .ply files have fields to take weights from (a .xyz file's weights are its "
                "4th column)");
  PointFile file;
  if (pcl_format)
    file = readWithPcl (path, ext == ".pcd", weight_field);
  else if (ext == ".xyz" || ext == ".txt")
    file = readXyz (path);
  else if (ext == ".off")
    file.points = readOff (path);
  else if (ext == ".obj")
    file.points = readObj (path);
  else
    fail (path, "unknown input format '" + ext + "' (expected .pcd, .ply, .xyz, .txt, .off or .obj)");
  if (file.points.empty ())
    fail (path, "no points");
  for (std::size_t i = 0; i < file.weights.size (); ++i)
  {
    const Point3& p = file.points[i];
    if (std::isfinite (p[0]) && std::isfinite (p[1]) && std::isfinite (p[2]) && !std::isfinite (file.weights[i]))
      fail (path, "point " + std::to_string (i) + ": the weight is not finite");
  }
  return file;
}

std::vector<Point3>
readPoints (const std::string& path)
{
  return readPointFile (path).points;
}

} // namespace pcl_wrap::apps
