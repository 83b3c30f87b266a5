// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The reader of an ASCII PLY file's vertices against PCL's own: the same cloud, fields and bytes,
// on headers with properties of every type, colours with and without alpha, an intensity, normals
// and faces after the vertices, read in windows and tasks of a few bytes and more; the headers it
// leaves to PCL's reader; and a clear error, naming the data line, for each way the data can be
// wrong.
#include "ascii_rows.h"
#include "ply_ascii.h"
#include "point_file.h"
#include "support/point_file_error.h"

#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <unistd.h>

namespace pcl_wrap::test
{
namespace
{

const std::string PATH = "/tmp/pcl_wrap_test_ply_ascii_" + std::to_string (::getpid ()) + ".ply";

void
writeFile (const std::string& text)
{
  std::ofstream (PATH, std::ios::binary) << text;
}

/** The cloud of PATH as readPointFile() reads a plain ASCII PLY file, in windows and tasks of the
  * given sizes; the error, if any, in \a error. */
pcl::PCLPointCloud2
readOurs (std::size_t window, std::size_t chunk, std::string& error)
{
  std::ifstream in (PATH, std::ios::binary);
  std::optional<apps::PlyVertexLayout> layout = apps::plainAsciiPlyLayout (in);
  EXPECT_TRUE (layout);
  if (!layout)
    return {};
  in.seekg (0, std::ios::end);
  const auto bytes = static_cast<std::uintmax_t> (in.tellg ()) - layout->data_start;
  in.seekg (std::streamoff (layout->data_start));
  pcl::PCLPointCloud2 cloud = std::move (layout->cloud);
  error =
      apps::readAsciiRows (in, bytes, layout->values, cloud.point_step, cloud.width, true, cloud.data, window, chunk);
  return cloud;
}

/** A property's random value, as text: a float to 9 digits, a double to 17, a whole number in
  * the type's range. */
std::string
randomValue (const std::string& type, std::mt19937_64& random)
{
  char text[64];
  if (type == "float" || type == "double")
  {
    std::uniform_real_distribution<double> mantissa (-10.0, 10.0);
    std::uniform_int_distribution<int> exponent (-20, 20);
    std::snprintf (text, sizeof text, type == "float" ? "%.9g" : "%.17g",
                   std::ldexp (mantissa (random), exponent (random)));
    return text;
  }
  const std::pair<long long, long long> range = type == "uchar"    ? std::pair (0LL, 255LL)
                                                : type == "char"   ? std::pair (-128LL, 127LL)
                                                : type == "short"  ? std::pair (-32768LL, 32767LL)
                                                : type == "ushort" ? std::pair (0LL, 65535LL)
                                                : type == "int"    ? std::pair (-2147483648LL, 2147483647LL)
                                                                   : std::pair (0LL, 4294967295LL);
  return std::to_string (std::uniform_int_distribution<long long> (range.first, range.second) (random));
}

/** An ASCII PLY file of \a vertices vertices with the given (type, name) properties, and then as
  * many triangles, when \a faces. */
std::string
plyText (const std::vector<std::pair<std::string, std::string>>& properties, std::size_t vertices, bool faces,
         std::mt19937_64& random)
{
  std::string text =
      "ply\nformat ascii 1.0\ncomment made by a test\nelement vertex " + std::to_string (vertices) + "\n";
  for (const auto& [type, name] : properties)
    text += "property " + type + " " + name + "\n";
  if (faces)
    text += "element face " + std::to_string (vertices) + "\nproperty list uchar int vertex_indices\n";
  text += "end_header\n";
  for (std::size_t v = 0; v < vertices; ++v)
  {
    for (std::size_t k = 0; k < properties.size (); ++k)
      text += (k ? " " : "") + randomValue (properties[k].first, random);
    text += "\n";
  }
  for (std::size_t f = 0; faces && f < vertices; ++f)
    text += "3 " + std::to_string (f) + " " + std::to_string ((f + 1) % vertices) + " " +
            std::to_string ((f + 2) % vertices) + "\n";
  return text;
}

TEST (PlyAscii, SameCloudAsPclsReader)
{
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  using Properties = std::vector<std::pair<std::string, std::string>>;
  const Properties xyz = {{"float", "x"}, {"float", "y"}, {"float", "z"}};
  const Properties headers[] = {
      xyz,
      {{"double", "x"}, {"double", "y"}, {"double", "z"}, {"float", "nx"}, {"float", "ny"}, {"float", "nz"}},
      {{"float", "x"}, {"float", "y"}, {"float", "z"}, {"uchar", "red"}, {"uchar", "green"}, {"uchar", "blue"}},
      {{"float", "x"},
       {"uchar", "red"},
       {"uchar", "green"},
       {"uchar", "blue"},
       {"uchar", "alpha"},
       {"float", "y"},
       {"float", "z"},
       {"uchar", "intensity"}},
      {{"double", "x"},
       {"double", "y"},
       {"double", "z"},
       {"float", "intensity"},
       {"uchar", "quality"},
       {"int", "label"},
       {"uint", "count"},
       {"short", "s"},
       {"ushort", "us"},
       {"char", "c"},
       {"float", "red"}},
  };
  std::mt19937_64 random (11);
  for (const Properties& properties : headers)
    for (std::size_t vertices : {std::size_t (1), std::size_t (3), std::size_t (200)})
      for (bool faces : {false, true})
      {
        writeFile (plyText (properties, vertices, faces, random));
        pcl::PCLPointCloud2 expected;
        ASSERT_EQ (pcl::io::loadPLYFile (PATH, expected), 0);
        for (std::size_t window : {std::size_t (1), std::size_t (7), std::size_t (64), std::size_t (1) << 25})
          for (std::size_t chunk : {std::size_t (1), std::size_t (3), std::size_t (50), std::size_t (1) << 18})
          {
            SCOPED_TRACE (properties[properties.size () - 1].second + ", " + std::to_string (vertices) +
                          " vertices, faces " + std::to_string (faces) + ", windows of " + std::to_string (window) +
                          ", tasks of " + std::to_string (chunk));
            std::string error;
            const pcl::PCLPointCloud2 read = readOurs (window, chunk, error);
            EXPECT_EQ (error, "");
            ASSERT_EQ (read.fields.size (), expected.fields.size ());
            for (std::size_t f = 0; f < read.fields.size (); ++f)
            {
              EXPECT_EQ (read.fields[f].name, expected.fields[f].name);
              EXPECT_EQ (read.fields[f].offset, expected.fields[f].offset);
              EXPECT_EQ (read.fields[f].datatype, expected.fields[f].datatype);
              EXPECT_EQ (read.fields[f].count, expected.fields[f].count);
            }
            EXPECT_EQ (read.width, expected.width);
            EXPECT_EQ (read.height, expected.height);
            EXPECT_EQ (read.point_step, expected.point_step);
            EXPECT_EQ (read.row_step, expected.row_step);
            ASSERT_TRUE (read.data == expected.data);
          }
      }
  std::remove (PATH.c_str ());
}

TEST (PlyAscii, OtherHeadersAreLeftToPcl)
{
  const std::string vertex = "element vertex 1\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string data = "end_header\n1 2 3\n";
  const std::string headers[] = {
      "ply\nformat binary_little_endian 1.0\n" + vertex + data,
      "ply\nformat ascii 1.0\nelement camera 1\nproperty float view_px\n" + vertex + "end_header\n0\n1 2 3\n",
      "ply\nformat ascii 1.0\n" + vertex + "element camera 1\nproperty float view_px\nend_header\n1 2 3\n0\n",
      "ply\nformat ascii 1.0\n" + vertex + "property list uchar float extra\n" + "end_header\n1 2 3 1 0\n",
      "ply\nformat ascii 1.0\n" + vertex + "property uchar diffuse_red\nend_header\n1 2 3 4\n",
      "ply\nformat ascii 1.0\n" + vertex + "property uchar green\nproperty uchar red\nproperty uchar blue\n" +
          "end_header\n1 2 3 4 5 6\n",
      "ply\nformat ascii 1.0\n" + vertex + "property uchar alpha\nend_header\n1 2 3 4\n",
      "ply\nformat ascii 1.0\n" + vertex + "property uchar red\nproperty float t\nproperty uchar green\n" +
          "property uchar blue\nend_header\n1 2 3 4 5 6 7\n",
      "ply\r\nformat ascii 1.0\r\n" + vertex + data,
  };
  for (const std::string& header : headers)
  {
    SCOPED_TRACE (header);
    std::istringstream in (header);
    EXPECT_FALSE (apps::plainAsciiPlyLayout (in));
  }
  // Such a file is still read, by PCL's reader.
  writeFile ("ply\nformat ascii 1.0\nelement camera 1\nproperty float view_px\n" + vertex + "end_header\n0\n1 2 3\n");
  EXPECT_EQ (apps::readPointFile (PATH).points.size (), 1u);
  std::remove (PATH.c_str ());
}

TEST (PlyFile, PclsOwnFilesOfCloudsWithNanPointsGiveTheirFinitePoints)
{
  // Without a camera element, PCL's ASCII writer leaves NaN points out of the vertices but not out
  // of obj_info's num_cols, and an organised cloud gets a range grid; with one, every point is
  // written, as the binary writer writes them.
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 6; ++i)
    cloud.push_back (i % 3 == 1 ? pcl::PointXYZ (nan, nan, nan) : pcl::PointXYZ (float (i), 2.0f * float (i), 1.0f));
  const auto finite = [] (const apps::PointFile& file) {
    std::vector<Point3> out;
    for (const Point3& p : file.points)
      if (std::isfinite (p[0]) && std::isfinite (p[1]) && std::isfinite (p[2]))
        out.push_back (p);
    return out;
  };
  const std::vector<Point3> expected = {{0, 0, 1}, {2, 4, 1}, {3, 6, 1}, {5, 10, 1}};
  for (const bool organised : {false, true})
    for (const bool binary : {false, true})
      for (const bool camera : {false, true})
      {
        SCOPED_TRACE (std::string (organised ? "organised " : "") + (binary ? "binary" : "ASCII") +
                      (camera ? " with a camera" : ""));
        cloud.width = organised ? 3 : 6;
        cloud.height = organised ? 2 : 1;
        cloud.is_dense = false;
        ASSERT_EQ (pcl::PLYWriter ().write (PATH, cloud, binary, camera), 0);
        const apps::PointFile read = apps::readPointFile (PATH);
        EXPECT_EQ (finite (read), expected);
        EXPECT_LE (read.points.size (), 6u);
      }
  std::remove (PATH.c_str ());
}

TEST (PlyFile, HeadersThatMisleadPclsReaderAreRefused)
{
  const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  const std::string ascii = "end_header\n0 0 0\n1 0 0\n0 1 0\n";
  const std::string binary = "end_header\n" + std::string (36, '\0');
  const std::string colours = "vertex colours not as red, green, blue in a row, then alpha";
  const std::pair<std::string, std::string> cases[] = {
      // fewer places than vertices: PCL's reader would write past the cloud
      {"ply\nformat binary_little_endian 1.0\nobj_info num_cols 1\nobj_info num_rows 1\n" + vertex + binary,
       "obj_info's num_cols x num_rows is 1 points, the vertex element 3"},
      // more, without a range grid: it would add points of zeros
      {"ply\nformat binary_little_endian 1.0\n" + vertex + "obj_info num_cols 4\nobj_info num_rows 2\n" + binary,
       "obj_info's num_cols x num_rows is 8 points, the vertex element 3"},
      // a blank before obj_info, in either line-end convention: an assertion in PCL's reader
      {"ply\nformat ascii 1.0\n obj_info num_cols 3\n" + vertex + ascii,
       "an obj_info line that does not start with obj_info"},
      {"ply\r\nformat binary_little_endian 1.0\r\n\tobj_info num_cols 3\r\n",
       "an obj_info line that does not start with obj_info"},
      {"ply obj_info num_cols 1\nformat ascii 1.0\nobj_info num_rows 1\n" + vertex + ascii, "no ply magic"},
      {"ply\r\nformat ascii 1.0\nend_header\r\n", "a header line not ended by \"\\r\\n\" where the first one is"},
      {"ply\nformat ascii 1.0\n" + vertex + vertex + ascii + "0 0 0\n1 0 0\n0 1 0\n",
       "a second vertex element, or more than 2^32 - 1 vertices"},
      // a camera's viewport read with the data resizes the cloud
      {"ply\nformat ascii 1.0\nelement camera 1\nproperty int viewportx\nproperty int viewporty\n" + vertex +
           "end_header\n1 1\n0 0 0\n1 0 0\n0 1 0\n",
       "a camera's viewport or obj_info says 1 points, not the 3 it holds"},
      // colours that PCL's reader misplaces, or writes past the point
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar red\nproperty float x\nproperty float y\n"
       "property float z\nproperty uchar green\nproperty uchar blue\nend_header\n9 0 0 1 1 2\n",
       colours},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
       "property uchar red\nproperty uchar blue\nproperty uchar diffuse_blue\nend_header\n0 0 1 1 2 3\n",
       colours},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
       "property uchar red\nproperty uchar green\nend_header\n0 0 1 1 2\n",
       colours},
      {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
       "property uchar red\nproperty uchar green\nproperty uchar alpha\nproperty uchar blue\nend_header\n0 0 1 1 2 3 "
       "4\n",
       colours},
      // a range grid of other cells than num_cols x num_rows
      {"ply\nformat ascii 1.0\nobj_info num_cols 2\nobj_info num_rows 2\n" + vertex +
           "element range_grid 5\nproperty list uchar int vertex_indices\n" + ascii + "1 0\n1 1\n1 2\n0\n0\n",
       "obj_info's num_cols x num_rows is 4 points, the range grid 5"},
  };
  for (const auto& [text, message] : cases)
  {
    SCOPED_TRACE (text);
    writeFile (text);
    EXPECT_EQ (pointFileError (PATH), PATH + ": malformed PLY file: " + message);
  }
  // Places for every vertex, as PCL's writer declares them, read as the vertices alone.
  writeFile ("ply\nformat ascii 1.0\nobj_info num_cols 5\nobj_info num_rows 1\n" + vertex + ascii);
  EXPECT_EQ (apps::readPointFile (PATH).points.size (), 3u);
  std::remove (PATH.c_str ());
}

TEST (PlyAscii, WrongDataNamesItsLine)
{
  const std::string header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
                             "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  const std::pair<std::string, std::string> cases[] = {
      {"0 0 0 1 2 3\n1 x 0 1 2 3\n0 1 0 1 2 3\n3 0 1 2\n", "data line 2: not a number"},
      {"0 0 0 1 2 3\n\n1 0 1 2 3\n0 1 0 1 2 3\n3 0 1 2\n", "data line 3: 5 numbers where a point has 6"},
      {"0 0 0 1 2 3\n1 0 0 1 256 3\n0 1 0 1 2 3\n3 0 1 2\n", "data line 2: '256' does not fit field green"},
      {"0 0 0 1 2 3\n1 0 0 1 2 3\n0 1 0 1 2 3\n3 0 1 two\n", "data line 4: not a number"},
      {"0 0 0 1 2 3\n1 0 0 1 2 3\n3 0 1 2\n0 0 0 0 0 0 0 0 0 0\n", "data line 3: 4 numbers where a point has 6"},
      {"# a comment\n0 0 0 1 2 3\n1 0 0 1 2 3\n0 1 0 1 2 3\n3 0 1 2\n", ""},
  };
  for (const auto& [text, message] : cases)
  {
    SCOPED_TRACE (text);
    writeFile (header + text);
    for (std::size_t window : {std::size_t (1), std::size_t (5), std::size_t (1) << 25})
    {
      std::string error;
      readOurs (window, 2, error);
      EXPECT_EQ (error, message);
    }
    EXPECT_EQ (pointFileError (PATH), message.empty () ? "" : PATH + ": malformed PLY file: " + message);
    if (message.empty ())
      EXPECT_EQ (apps::readPointFile (PATH).points.size (), 3u);
  }
  std::remove (PATH.c_str ());
}

} // namespace
} // namespace pcl_wrap::test
