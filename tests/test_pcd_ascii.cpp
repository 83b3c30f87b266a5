// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The ASCII PCD reader against PCL's own: the same cloud, byte for byte, on files with fields of
// every type and count, blank lines and NaNs, read in windows and tasks of a few bytes and more;
// the colours PCL's writer writes read back; and a clear error, naming the data
// line, for each way the data can be wrong.
#include "pcd_ascii.h"
#include "point_file.h"
#include "support/point_file_error.h"

#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <unistd.h>

namespace pcl_wrap::test
{
namespace
{

const std::string DIR = "/tmp/pcl_wrap_test_pcd_ascii_" + std::to_string (::getpid ()) + "_";

std::string
writeFile (const std::string& name, const std::string& text)
{
  const std::string path = DIR + name;
  std::ofstream (path, std::ios::binary) << text;
  return path;
}

/** The cloud of \a path read as readPointFile() reads an ASCII PCD file, in windows and tasks of
  * the given sizes; the error, if any, in \a error. */
pcl::PCLPointCloud2
readOurs (const std::string& path, std::size_t window, std::size_t chunk, std::string& error)
{
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  int version = 0, type = 0;
  unsigned int start = 0;
  pcl::PCDReader reader;
  EXPECT_EQ (reader.readHeader (path, cloud, origin, orientation, version, type, start), 0);
  EXPECT_EQ (type, 0);
  std::ifstream in (path, std::ios::binary);
  in.seekg (0, std::ios::end);
  const auto bytes = static_cast<std::uintmax_t> (in.tellg ()) - start;
  in.seekg (start);
  error = apps::readPcdAsciiData (in, bytes, cloud, window, chunk);
  return cloud;
}

/** A header for \a points points of the given fields. */
std::string
header (const std::string& fields, const std::string& sizes, const std::string& types, const std::string& counts,
        std::size_t points)
{
  return "# .PCD v0.7\nVERSION 0.7\nFIELDS " + fields + "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT " + counts +
         "\nWIDTH " + std::to_string (points) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " +
         std::to_string (points) + "\nDATA ascii\n";
}

/** Random points with a value of each type: floats written to 9 digits, doubles to 17, whole
  * numbers of each integer type, an occasional "nan", blank lines and '\r' line ends. */
std::string
mixedCloud (std::size_t points, std::mt19937_64& random)
{
  std::uniform_real_distribution<double> mantissa (-10.0, 10.0);
  std::uniform_int_distribution<int> exponent (-20, 20), small (-128, 127), byte (0, 255), any (0, 99);
  std::uniform_int_distribution<std::int64_t> wide (-(std::int64_t (1) << 62), std::int64_t (1) << 62);
  std::string text = header ("x y z normal intensity label ring t _ flags", "4 4 4 8 4 4 2 1 4 1",
                             "F F F F F U U I F I", "1 1 1 3 1 1 1 1 1 2", points);
  char number[64];
  for (std::size_t i = 0; i < points; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      std::snprintf (number, sizeof number, "%.9g ", std::ldexp (mantissa (random), exponent (random)));
      text += any (random) == 0 ? std::string ("nan ") : number;
    }
    for (int c = 0; c < 3; ++c)
    {
      std::snprintf (number, sizeof number, "%.17g ", std::ldexp (mantissa (random), exponent (random)));
      text += number;
    }
    std::snprintf (number, sizeof number, "%.9g ", mantissa (random));
    text += number;
    text += std::to_string (std::uint32_t (wide (random))) + " " + std::to_string (byte (random) * 200) + " " +
            std::to_string (small (random)) + " 7 " + std::to_string (small (random)) + "\t" +
            std::to_string (small (random)) + (any (random) < 10 ? "\r\n" : "\n");
    if (any (random) == 0)
      text += "\n";
  }
  return text;
}

TEST (PcdAscii, SameCloudAsPclsReader)
{
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  std::mt19937_64 random (7);
  for (std::size_t points : {std::size_t (1), std::size_t (2), std::size_t (37), std::size_t (500)})
  {
    const std::string path = writeFile ("mixed.pcd", mixedCloud (points, random));
    pcl::PCLPointCloud2 expected;
    ASSERT_EQ (pcl::io::loadPCDFile (path, expected), 0);
    for (std::size_t window : {std::size_t (1), std::size_t (7), std::size_t (64), std::size_t (1) << 25})
      for (std::size_t chunk : {std::size_t (1), std::size_t (3), std::size_t (50), std::size_t (1) << 18})
      {
        SCOPED_TRACE (std::to_string (points) + " points, windows of " + std::to_string (window) + ", tasks of " +
                      std::to_string (chunk));
        std::string error;
        const pcl::PCLPointCloud2 read = readOurs (path, window, chunk, error);
        EXPECT_EQ (error, "");
        ASSERT_EQ (read.data.size (), expected.data.size ());
        // A padding field ("_") holds nothing: its bytes are left out of the comparison.
        const std::size_t padding = expected.fields[8].offset;
        for (std::size_t p = 0; p < points; ++p)
          for (std::size_t b = 0; b < expected.point_step; ++b)
            if (b < padding || b >= padding + 4)
              ASSERT_EQ (read.data[p * expected.point_step + b], expected.data[p * expected.point_step + b])
                  << "point " << p << ", byte " << b;
      }
  }
  std::remove ((DIR + "mixed.pcd").c_str ());
}

TEST (PcdAscii, ColoursFromPclsWriterReadBack)
{
  // PCL's writer writes an "rgb" field's packed bits as a whole number of type U.
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  for (int i = 0; i < 50; ++i)
  {
    pcl::PointXYZRGB p;
    p.x = float (i);
    p.y = float (i % 7);
    p.z = float (i % 3);
    p.r = std::uint8_t (5 * i);
    p.g = std::uint8_t (255 - i);
    p.b = std::uint8_t (i * i);
    cloud.push_back (p);
  }
  const std::string path = DIR + "rgb.pcd";
  ASSERT_EQ (pcl::io::savePCDFileASCII (path, cloud), 0);
  const apps::PointFile file = apps::readPointFile (path);
  ASSERT_EQ (file.points.size (), cloud.size ());
  ASSERT_EQ (file.attributes.colours.size (), cloud.size ());
  for (std::size_t i = 0; i < cloud.size (); ++i)
  {
    EXPECT_EQ (file.points[i][0], cloud[i].x);
    EXPECT_EQ (file.attributes.colours[i][0], cloud[i].r) << i;
    EXPECT_EQ (file.attributes.colours[i][1], cloud[i].g) << i;
    EXPECT_EQ (file.attributes.colours[i][2], cloud[i].b) << i;
  }
  std::remove (path.c_str ());
}

TEST (PcdAscii, CommentsAndBlankLinesAreSkipped)
{
  const std::string path =
      writeFile ("comments.pcd", header ("x y z", "4 4 8", "F F F", "1 1 1", 2) +
                                     "\n   \n# a comment\n1 2 3 # the first\n\t\n4.5 -6 +7e2\n# the end\n");
  std::string error;
  const pcl::PCLPointCloud2 cloud = readOurs (path, 1 << 20, 1 << 18, error);
  EXPECT_EQ (error, "");
  ASSERT_EQ (cloud.data.size (), 2 * cloud.point_step);
  float x;
  double z;
  std::memcpy (&x, &cloud.data[cloud.point_step], 4);
  std::memcpy (&z, &cloud.data[cloud.point_step + 8], 8);
  EXPECT_EQ (x, 4.5f);
  EXPECT_EQ (z, 700.0);
  std::remove (path.c_str ());
}

TEST (PcdAscii, WrongDataNamesItsLine)
{
  const std::string xyz = header ("x y z", "4 4 4", "F F F", "1 1 1", 3);
  const std::string labelled = header ("x y z label", "4 4 4 1", "F F F U", "1 1 1 1", 2);
  const std::pair<std::string, std::string> cases[] = {
      {xyz + "0 0 0\n1 x 0\n0 1 0\n", "data line 2: not a number"},
      {xyz + "0 0 0\n\n1 0\n0 1 0\n", "data line 3: 2 numbers where a point has 3"},
      {xyz + "0 0 0\n1 0 0 5\n0 1 0\n", "data line 2: 4 numbers where a point has 3"},
      {xyz + "0 0 0\n1 0 0\n# as long as three points\n", "2 points where 3 are declared"},
      {xyz + "0 0 0\n1 0 0\n0 1 0\n0 0 1\n", "data line 4: more points than the 3 declared"},
      {labelled + "0 0 0 1\n1 0 0 1.5\n", "data line 2: '1.5' does not fit field label"},
      {labelled + "0 0 0 256\n1 0 0 1\n", "data line 1: '256' does not fit field label"},
      {labelled + "0 0 0 -1\n1 0 0 1\n", "data line 1: '-1' does not fit field label"},
      {labelled + "0 0 0 nan\n1 0 0 1\n", "data line 1: 'nan' does not fit field label"},
      {labelled + "0 0 0 2e2\n1 0 0 +3\n", ""},
  };
  for (const auto& [text, message] : cases)
  {
    SCOPED_TRACE (text);
    const std::string path = writeFile ("wrong.pcd", text);
    for (std::size_t window : {std::size_t (1), std::size_t (5), std::size_t (1) << 25})
    {
      std::string error;
      readOurs (path, window, 2, error);
      EXPECT_EQ (error, message);
    }
    // The command-line tool's reader says the same, with the file's name.
    EXPECT_EQ (pointFileError (path), message.empty () ? "" : path + ": malformed PCD file: " + message);
  }
  std::remove ((DIR + "wrong.pcd").c_str ());
}

TEST (PcdAscii, WholeNumbersFillTheirTypesRange)
{
  const std::string path =
      writeFile ("ranges.pcd", header ("x y z a b c d", "4 4 4 1 2 8 8", "F F F I U I U", "1 1 1 1 1 1 1", 2) +
                                   "0 0 0 -128 65535 -9223372036854775808 18446744073709551615\n"
                                   "1e39 -1e39 3.4028235e38 127 0 9223372036854775807 0\n");
  std::string error;
  const pcl::PCLPointCloud2 cloud = readOurs (path, 1 << 20, 1 << 18, error);
  ASSERT_EQ (error, "");
  const std::uint8_t* first = cloud.data.data ();
  const std::uint8_t* second = first + cloud.point_step;
  std::int8_t a;
  std::uint16_t b;
  std::int64_t c;
  std::uint64_t d;
  std::memcpy (&a, first + cloud.fields[3].offset, 1);
  std::memcpy (&b, first + cloud.fields[4].offset, 2);
  std::memcpy (&c, first + cloud.fields[5].offset, 8);
  std::memcpy (&d, first + cloud.fields[6].offset, 8);
  EXPECT_EQ (a, -128);
  EXPECT_EQ (b, 65535);
  EXPECT_EQ (c, std::numeric_limits<std::int64_t>::min ());
  EXPECT_EQ (d, std::numeric_limits<std::uint64_t>::max ());
  std::memcpy (&c, second + cloud.fields[5].offset, 8);
  EXPECT_EQ (c, std::numeric_limits<std::int64_t>::max ());
  float x, y, z;
  std::memcpy (&x, second, 4);
  std::memcpy (&y, second + 4, 4);
  std::memcpy (&z, second + 8, 4);
  EXPECT_EQ (x, std::numeric_limits<float>::infinity ());
  EXPECT_EQ (y, -std::numeric_limits<float>::infinity ());
  EXPECT_EQ (z, std::numeric_limits<float>::max ());
  std::remove (path.c_str ());
}

} // namespace
} // namespace pcl_wrap::test
