// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The .off reader's parallel parse of the vertex lines against the line-by-line reading it
// replaces: the same vertices bit for bit, or the same first error, on edge cases, random bytes
// and meshes with a bad line at each place, read in windows and tasks of a few bytes and more.
#include "support/off_reference.h"
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
expectSameAsReference (const std::string& text, std::size_t window_bytes, std::size_t chunk_bytes)
{
  const apps::OffVertices expected = referenceOffVertices (text);
  std::istringstream in (text);
  const apps::OffVertices parsed = apps::readOffStream (in, window_bytes, chunk_bytes);
  EXPECT_TRUE (sameOffVertices (parsed, expected))
      << "text (" << text.size () << " bytes, windows of " << window_bytes << ", tasks of " << chunk_bytes << "): '"
      << text.substr (0, 200) << "'\nexpected: " << expected.error << " " << expected.values.size () << " values of "
      << expected.begin.size () << " vertices\nparsed: " << parsed.error << " " << parsed.values.size ()
      << " values of " << parsed.begin.size () << " vertices";
}

void
expectSameAsReference (const std::string& text)
{
  for (std::size_t window : {std::size_t (1), std::size_t (7), std::size_t (64), std::size_t (1) << 25})
    for (std::size_t chunk : {std::size_t (1), std::size_t (3), std::size_t (50), std::size_t (1) << 18})
      expectSameAsReference (text, window, chunk);
}

/** An .off mesh's text: \a vertices lines of \a numbers random numbers written to the last bit,
  * then a face per vertex. */
std::string
offText (const std::string& header, std::size_t vertices, int numbers, std::mt19937_64& random)
{
  std::uniform_real_distribution<double> mantissa (-10.0, 10.0);
  std::uniform_int_distribution<int> exponent (-30, 30);
  std::string text = header + "\n" + std::to_string (vertices) + " " + std::to_string (vertices) + " 0\n";
  char number[40];
  for (std::size_t i = 0; i < vertices; ++i)
  {
    for (int c = 0; c < numbers; ++c)
    {
      std::snprintf (number, sizeof number, c % 2 ? "%.17g " : "%.6g ",
                     std::ldexp (mantissa (random), exponent (random)));
      text += number;
    }
    text += "\n";
  }
  for (std::size_t i = 0; i < vertices; ++i)
    text += "3 " + std::to_string (i) + " " + std::to_string ((i + 1) % vertices) + " " +
            std::to_string ((i + 2) % vertices) + "\n";
  return text;
}

TEST (OffText, EdgeCasesReadAsLineByLine)
{
  const std::string cases[] = {"",
                               "\n",
                               "OFF",
                               "OFF\n",
                               "OFF\n0 0 0\n",
                               "OFF 0 0 0",
                               "OFF\n1 0 0\n1 2 3",
                               "OFF\n1 0 0\n1 2 3\n",
                               "OFF 2 0 0\n1 2 3\n4 5 6\n",
                               "OFF\n2 0 0\n1 2 3\n",
                               "OFF\n2 0 0\n1 2 3\n4 5\n",
                               "OFF\n2 0 0\n1 2 3\n4 five 6\n",
                               "OFF\n1 0 0\n1 2 3\nnot a face\n",
                               "OFF\n1 0 0\n1 2 3\n4 5\n",
                               "# a comment\n\nOFF\n# counts\n\n2 0 0\n\n1 2 3\n# between\n4 5 6\n",
                               "OFF\n-1 0 0\n",
                               "OFF\n1.5 0 0\n1 2 3\n",
                               "OFF\nnan 0 0\n",
                               "OFF\n1e20 0 0\n1 2 3\n",
                               "OFF\ntwo 0 0\n",
                               "COFF\n2 0 0\n1 2 3 0.5 0.5 0.5\n4 5 6 1 1 1 1\n",
                               "COFF\n1 0 0\n1 2 3 0.5 0.5\n",
                               "NOFF\n1 0 0\n1 2 3 0 0 1\n",
                               "CNOFF\n1 0 0\n1 2 3 0 0 1 255 0 0 255\n",
                               "STCNOFF\n1 0 0\n1 2 3 0 0 1 255 0 0 0.5 0.5\n",
                               "4OFF\n1 0 0\n1 2 3 4\n",
                               "OFFX\n1 0 0\n1 2 3\n",
                               "OF\n",
                               "off\n1 0 0\n1 2 3\n",
                               "OFF\r\n1 0 0\r\n1 2 3\r\n",
                               "OFF\n1 0 0\n0x1p3 +1 inf\n",
                               "OFF\n1 0 0\n1e400 0 0\n",
                               "OFF\n1 0 0\n1 2 3 # 4\n",
                               "OFF\n2 0 0\n1 2 # 3\n4 5 6\n",
                               std::string ("OFF\n1 0 0\n1 2 3\0 junk\n", 22),
                               std::string ("OFF\n1 0 0\n1\0x 2 3\n", 18),
                               "OFF\n1 0 0\n" + std::string (800, '7') + " 2 3\n"};
  for (const std::string& text : cases)
    expectSameAsReference (text);
}

TEST (OffText, RandomBytesReadAsLineByLine)
{
  std::mt19937_64 random (7);
  using namespace std::string_literals; // "\0"s: a token of one NUL byte
  const std::vector<std::string> tokens = {"1", "-2.5", "3e4", "0x1p3", "+7", "inf", "nan",  "#",
                                           " ", " ",    "\t",  "\n",    "\n", "\n",  "\r",   "e",
                                           ".", "x",    "1e",  "9",     "\v", "\0"s, "1e999"};
  const std::string headers[] = {"OFF\n", "OFF 3 ", "COFF\n", "NOFF\n2 0 0\n", "OFF\n4 1 0\n", "CNOFF\n1\n"};
  for (int round = 0; round < 1500; ++round)
  {
    std::string text = headers[random () % 6];
    text += test::randomTokenText (random, tokens);
    const std::size_t window = 1 + random () % 16, chunk = 1 + random () % 16;
    expectSameAsReference (text, window, chunk);
  }
}

TEST (OffText, BadLineAtEveryPlaceAgrees)
{
  // A bad line at each place in turn: before the last vertex it is an error, after it (among the
  // faces) it is not read.
  std::mt19937_64 random (11);
  const std::string mesh = offText ("OFF", 20, 3, random);
  expectSameAsReference (mesh);
  expectSameAsReference (offText ("COFF", 20, 7, random));
  for (std::size_t at = mesh.find ('\n') + 1; at < mesh.size (); at = mesh.find ('\n', at) + 1)
    for (const char* bad : {"1 2\n", "1 two 3\n", "# a comment\n", "\n"})
      for (std::size_t window : {std::size_t (5), std::size_t (1) << 25})
        for (std::size_t chunk : {std::size_t (1), std::size_t (40)})
          expectSameAsReference (mesh.substr (0, at) + bad + mesh.substr (at), window, chunk);
  // A mesh as large as a scan's: the same numbers, bit for bit.
  const std::string large = offText ("OFF", 100000, 3, random);
  expectSameAsReference (large, std::size_t (1) << 25, std::size_t (1) << 18);
  expectSameAsReference (large, std::size_t (1) << 20, std::size_t (1) << 12);
}

} // namespace
} // namespace pcl_wrap::test
