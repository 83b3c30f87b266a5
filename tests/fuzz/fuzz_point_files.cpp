// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// libFuzzer: arbitrary bytes as each input format of the command-line tool. A file either reads
// or gives a FileError; anything else (a crash, another exception) is a finding. The bytes are
// also read as a .xyz, .obj and .off file's text in tasks of a few bytes, and from a stream in
// windows of a few bytes, which must give what a reading line by line gives; and as an ASCII PCD
// file's data, which must read the same in windows and tasks of a few bytes as in large ones.
#include "pcd_ascii.h"
#include "point_file.h"
#include "support/obj_reference.h"
#include "support/off_reference.h"
#include "support/xyz_reference.h"

#include <pcl/common/io.h>
#include <pcl/console/print.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace
{

/** A cloud of four points whose fields take a float, an unsigned byte, a padding float and two
  * doubles a line, as PCL's header reader would leave it. */
pcl::PCLPointCloud2
pcdCloud ()
{
  pcl::PCLPointCloud2 cloud;
  const auto field = [&] (const char* name, std::uint8_t type, std::uint32_t count) {
    pcl::PCLPointField f;
    f.name = name;
    f.datatype = type;
    f.count = count;
    f.offset = cloud.point_step;
    cloud.point_step += count * static_cast<std::uint32_t> (pcl::getFieldSize (type));
    cloud.fields.push_back (f);
  };
  field ("x", pcl::PCLPointField::FLOAT32, 1);
  field ("i", pcl::PCLPointField::UINT8, 1);
  field ("_", pcl::PCLPointField::FLOAT32, 1);
  field ("n", pcl::PCLPointField::FLOAT64, 2);
  cloud.width = 4;
  cloud.height = 1;
  cloud.data.resize (4 * cloud.point_step);
  return cloud;
}

} // namespace

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static const char* const EXTENSIONS[] = {".xyz", ".off", ".obj", ".ply", ".pcd"};
  static const std::string stem = "/tmp/pcl_wrap_fuzz_" + std::to_string (::getpid ());
  pcl::console::setVerbosityLevel (pcl::console::L_ALWAYS);
  if (size < 1)
    return 0;
  const std::string bytes (reinterpret_cast<const char*> (data + 1), size - 1);
  const pcl_wrap::apps::XyzTable reference = pcl_wrap::test::referenceXyzTable (bytes);
  std::istringstream stream (bytes);
  if (!pcl_wrap::test::sameXyzTables (pcl_wrap::apps::parseXyzText (bytes, 1 + data[0] % 32), reference) ||
      !pcl_wrap::test::sameXyzTables (pcl_wrap::apps::readXyzStream (stream, 0, 1 + data[0] % 16), reference))
    __builtin_trap ();
  const pcl_wrap::apps::ObjVertices obj = pcl_wrap::test::referenceObjVertices (bytes);
  std::istringstream obj_stream (bytes);
  if (!pcl_wrap::test::sameObjVertices (pcl_wrap::apps::parseObjText (bytes, 1 + data[0] % 32), obj) ||
      !pcl_wrap::test::sameObjVertices (pcl_wrap::apps::readObjStream (obj_stream, 0, 1 + data[0] % 16), obj))
    __builtin_trap ();
  std::istringstream off_stream (bytes);
  if (!pcl_wrap::test::sameOffVertices (pcl_wrap::apps::readOffStream (off_stream, 1 + data[0] % 16, 1 + data[0] % 32),
                                        pcl_wrap::test::referenceOffVertices (bytes)))
    __builtin_trap ();
  pcl::PCLPointCloud2 in_windows = pcdCloud (), at_once = pcdCloud ();
  std::istringstream pcd_stream (bytes), pcd_again (bytes);
  if (pcl_wrap::apps::readPcdAsciiData (pcd_stream, 0, in_windows, 1 + data[0] % 16, 1 + data[0] % 32) !=
          pcl_wrap::apps::readPcdAsciiData (pcd_again, bytes.size (), at_once) ||
      in_windows.data != at_once.data)
    __builtin_trap ();
  const std::string path = stem + EXTENSIONS[data[0] % 5];
  std::ofstream (path, std::ios::binary).write (reinterpret_cast<const char*> (data + 1), std::streamsize (size - 1));
  try
  {
    pcl_wrap::apps::readPoints (path);
  }
  catch (const pcl_wrap::apps::FileError&)
  {
  }
  std::remove (path.c_str ());
  return 0;
}
