// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The .obj reader's parallel parse against the line-by-line reading it replaces: the same
// vertices, colours and normals bit for bit, or the same first error, on edge cases, random bytes
// and texts cut into tasks at every line, and read from a stream a window at a time.
#include "support/obj_reference.h"
#include "support/random_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>

namespace pcl_wrap::test
{
namespace
{

void
expectSameAsReference (const std::string& text, std::size_t chunk_bytes)
{
  const apps::ObjVertices expected = referenceObjVertices (text);
  const apps::ObjVertices parsed = apps::parseObjText (text, chunk_bytes);
  EXPECT_TRUE (sameObjVertices (parsed, expected))
      << "text (" << text.size () << " bytes, tasks of " << chunk_bytes << "): '" << text.substr (0, 200)
      << "'\nexpected: " << expected.error << " " << expected.points.size () << " coordinates, "
      << expected.colours.size () << " colour values, " << expected.normals.size () << " normal values"
      << "\nparsed: " << parsed.error << " " << parsed.points.size () << " coordinates, " << parsed.colours.size ()
      << " colour values, " << parsed.normals.size () << " normal values";
}

/** A mesh's text: "v" lines of 3 or 6 random numbers written to the last bit (6 on every line with
  * \a coloured), a "vn" line after each with \a normals, and a face after every third vertex. */
std::string
objLines (std::size_t vertices, bool coloured, bool normals, std::mt19937_64& random)
{
  std::uniform_real_distribution<double> mantissa (-10.0, 10.0);
  std::uniform_int_distribution<int> exponent (-30, 30);
  const auto numbers = [&] (int count) {
    std::string text;
    char number[40];
    for (int c = 0; c < count; ++c)
    {
      std::snprintf (number, sizeof number, c % 2 ? " %.17g" : " %.6g",
                     std::ldexp (mantissa (random), exponent (random)));
      text += number;
    }
    return text;
  };
  std::string text = "# a mesh\no mesh\n";
  for (std::size_t i = 0; i < vertices; ++i)
  {
    text += "v" + numbers (coloured ? 6 : 3) + "\n";
    if (normals)
      text += "vn" + numbers (3) + "\n";
    if (i % 3 == 2)
      text += "f " + std::to_string (i - 1) + " " + std::to_string (i) + " " + std::to_string (i + 1) + "\n";
  }
  return text;
}

TEST (ObjText, EdgeCasesReadAsLineByLine)
{
  const std::string cases[] = {"",
                               "\n",
                               "v",
                               "v\n",
                               "v 1 2 3",
                               "v 1 2 3\n",
                               "v 1 2\n",
                               "v 1 2 3 4 5 6 7\n",
                               "v 1 2 3 4 5 6 7 8\n",
                               "v 1 2 3 0.5 0.5 0.5\nv 4 5 6 1 1 1\n",
                               "v 1 2 3 0.5 0.5 0.5\nv 4 5 6\n",
                               "v 1 2 3 0.5 0.5 0.5\nv 4 5 6 1 1 1 1\n",
                               "v 1 2 3\r\nv 4 5 6\r\n",
                               "v\t1\t2\t3\n",
                               "  \tv 1 2 3\n",
                               "v\r1 2 3\n",
                               "vn 0 0 1\n",
                               "vn 0 0\n",
                               "vn 0 0 1 1\n",
                               "vn 1e400 0 1\n",
                               "vt 0.5 0.5\nvp 1 2 3\nf 1 2 3\ng group\nusemtl x\n",
                               "v 1 2 3 # a comment\n",
                               "v 1 2 # 3\n",
                               "# v 1 2\n",
                               "V 1 2 3\n",
                               "v1 2 3\n",
                               "vv 1 2\n",
                               "v 0x1p3 +1 inf\n",
                               "v nan 1 2\n",
                               "v 1 two 3\n",
                               "v 1e400 0 0\n",
                               "v 4e-320 1 2\n",
                               std::string ("v 1 2 3\0 junk\n", 14),
                               std::string ("v\0 1 2 3\n", 9),
                               std::string ("\0v 1 2\n", 7),
                               std::string ("v 1\0x 2 3\n", 10),
                               "\xef\xbb\xbfv 1 2 3\n",
                               "v 1 2 3\nv " + std::string (800, '7') + " 2 3\n",
                               "v 1 2 3\nf 1 2\nv 4 5\n",
                               "v 1 2 3\nvn 1 0\nv 4 5\n"};
  for (const std::string& text : cases)
    for (std::size_t chunk : {std::size_t (1), std::size_t (3), std::size_t (1) << 18})
      expectSameAsReference (text, chunk);
}

TEST (ObjText, RandomBytesReadAsLineByLine)
{
  std::mt19937_64 random (7);
  using namespace std::string_literals; // "\0"s: a token of one NUL byte
  const std::vector<std::string> tokens = {"v",  "vn",  "v ",  "vn ", "f ", "1", "-2.5", "3e4", "0x1p3",
                                           "+7", "inf", "nan", "#",   " ",  " ", "\t",   "\n",  "\n",
                                           "\r", "e",   ".",   "x",   "1e", "9", "\v",   "\0"s, "1e999"};
  for (int round = 0; round < 3000; ++round)
  {
    const std::string text = test::randomTokenText (random, tokens);
    expectSameAsReference (text, 1 + random () % 16);
  }
}

TEST (ObjText, TasksCutAtEveryLineAgree)
{
  // A mesh long enough for many tasks, then a bad line at each place in turn, and a vertex
  // without colours: where a task starts, only the merge sees it.
  std::mt19937_64 random (11);
  const std::string coloured = objLines (40, true, true, random), plain = objLines (40, false, false, random);
  for (std::size_t chunk : {std::size_t (1), std::size_t (50), std::size_t (333), std::size_t (1) << 18})
  {
    expectSameAsReference (coloured, chunk);
    expectSameAsReference (plain, chunk);
    std::size_t at = 0;
    while (at < coloured.size ())
    {
      expectSameAsReference (coloured.substr (0, at) + "v 1 2\n" + coloured.substr (at), chunk);
      expectSameAsReference (coloured.substr (0, at) + "vn 1 two 3\n" + coloured.substr (at), chunk);
      expectSameAsReference (coloured.substr (0, at) + "v 1 2 3\n" + coloured.substr (at), chunk);
      at = coloured.find ('\n', at) + 1;
    }
  }
  // A mesh as large as a scan's: the same numbers, bit for bit.
  expectSameAsReference (objLines (100000, false, true, random), std::size_t (1) << 18);
}

TEST (ObjText, StreamReadInWindowsAgrees)
{
  std::mt19937_64 random (13);
  const std::string mesh = objLines (30, true, false, random);
  const std::vector<std::string> texts{mesh,
                                       mesh.substr (0, mesh.size () - 1),
                                       mesh + "v 1 2\n",
                                       "",
                                       "v 1 2 3",
                                       mesh + "vn " + std::string (3000, '5') + " 1 2\n" + mesh,
                                       mesh.substr (0, mesh.size () / 2) + "v 1 two 3\n" + mesh};
  for (const std::string& text : texts)
    for (std::size_t window :
         {std::size_t (1), std::size_t (7), std::size_t (64), std::size_t (1000), std::size_t (1) << 25})
      for (const std::size_t bytes : {text.size (), std::size_t (0)})
      {
        std::istringstream in (text);
        EXPECT_TRUE (sameObjVertices (apps::readObjStream (in, bytes, window), referenceObjVertices (text)))
            << "window " << window << ", text '" << text.substr (0, 100) << "'";
      }
}

} // namespace
} // namespace pcl_wrap::test
