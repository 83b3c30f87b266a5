// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// libFuzzer: arbitrary bytes as each input format of the command-line tool. A file either reads
// or gives a FileError; anything else (a crash, another exception) is a finding. The bytes are
// also read as a .xyz, .obj and .off file's text in tasks of a few bytes, and from a stream in
// windows of a few bytes, which must give what a reading line by line gives.
#include "point_file.h"
#include "support/obj_reference.h"
#include "support/off_reference.h"
#include "support/xyz_reference.h"

#include <pcl/console/print.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

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
