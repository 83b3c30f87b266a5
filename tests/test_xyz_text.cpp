// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The .xyz reader's parallel parse against the line-by-line reading it replaces: the same
// numbers bit for bit, or the same first error, on edge cases, random bytes and texts cut into
// tasks at every line, and read from a stream a window at a time.
#include "support/xyz_reference.h"
#include "support/random_text.h"

#include <gtest/gtest.h>

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
  const apps::XyzTable expected = referenceXyzTable (text);
  const apps::XyzTable parsed = apps::parseXyzText (text, chunk_bytes);
  EXPECT_TRUE (sameXyzTables (parsed, expected))
      << "text (" << text.size () << " bytes, tasks of " << chunk_bytes << "): '" << text.substr (0, 200)
      << "'\nexpected: " << expected.error << " " << expected.columns << " columns, " << expected.values.size ()
      << " values\nparsed: " << parsed.error << " " << parsed.columns << " columns, " << parsed.values.size ()
      << " values";
}

/** Lines of random numbers written to the last bit, with \a columns numbers each. */
std::string
numberLines (std::size_t lines, std::size_t columns, std::mt19937_64& random)
{
  std::uniform_real_distribution<double> mantissa (-10.0, 10.0);
  std::uniform_int_distribution<int> exponent (-30, 30);
  std::string text;
  char number[40];
  for (std::size_t i = 0; i < lines; ++i)
  {
    for (std::size_t c = 0; c < columns; ++c)
    {
      std::snprintf (number, sizeof number, c % 2 ? "%.17g" : "%.6g",
                     std::ldexp (mantissa (random), exponent (random)));
      text += (c ? " " : "") + std::string (number);
    }
    text += '\n';
  }
  return text;
}

TEST (XyzText, EdgeCasesReadAsLineByLine)
{
  const std::string cases[] = {"",
                               "\n",
                               "\n\n",
                               "# only a comment\n",
                               "1 2 3",
                               "1 2 3\n",
                               "1 2 3\r\n4 5 6\r\n",
                               " \t1\t2 3 \n\n",
                               "1 2\n",
                               "1 2 3 4\n5 6 7\n",
                               "1 2 3\n4 5 6 7\n",
                               "+1 +2 +3\n",
                               "0x1p3 0X1P-2 0x.8\n",
                               "inf -inf nan\n",
                               "INF Infinity -NaN\n",
                               "nan(123) 1 2\n",
                               "nan( 1 2\n",
                               "1e400 0 0\n",
                               "-1e400 0 0\n",
                               "1e-400 0 0\n",
                               "4e-320 1 2\n",
                               "1.5# a comment\n1 2 3",
                               "1 2 3#4\n",
                               "1\v2\f3\n",
                               std::string ("1 2 3\0 junk\n", 12),
                               std::string ("1\0x 2 3\n", 8),
                               std::string ("\0 1 2 3\n", 8),
                               std::string ("1 2 3\n\0", 7),
                               "1e 2 3\n",
                               "1e+ 2 3\n",
                               ". 2 3\n",
                               "- 2 3\n",
                               "-.5 .5 5.\n",
                               "0001 -0 00.0e-0\n",
                               "1,5 2 3\n",
                               "1 2 3\n\n\n4 five 6\n",
                               "1 2 3 4 5 6 7 8 9 10 11 12\n",
                               "\xef\xbb\xbf"
                               "1 2 3\n",
                               "1 2 3\n" + std::string (800, '7') + " 2 3\n",
                               "0." + std::string (400, '0') + "1 2 3\n",
                               "1 2 3\n#\n# 4 5\n6 7 8",
                               "1 2 3\n1 2 3 4\n1 2\n"};
  for (const std::string& text : cases)
    for (std::size_t chunk : {std::size_t (1), std::size_t (3), std::size_t (1) << 18})
      expectSameAsReference (text, chunk);
}

TEST (XyzText, RandomBytesReadAsLineByLine)
{
  std::mt19937_64 random (7);
  using namespace std::string_literals; // "\0"s: a token of one NUL byte
  const std::vector<std::string> tokens = {"1", "-2.5", "3e4", "0x1p3", "+7", "inf", "nan", "#",
                                           " ", " ",    "\t",  "\n",    "\n", "\r",  "e",   ".",
                                           "-", "x",    "1e",  "0.",    "9",  "\v",  "\0"s, "1e999"};
  for (int round = 0; round < 3000; ++round)
  {
    const std::string text = test::randomTokenText (random, tokens);
    expectSameAsReference (text, 1 + random () % 16);
  }
}

TEST (XyzText, TasksCutAtEveryLineAgree)
{
  // A table long enough for many tasks, then a line of another width at each place in turn, and
  // from there on all lines of another width: where a task starts, only the merge sees it.
  std::mt19937_64 random (11);
  const std::string three = numberLines (60, 3, random), four = numberLines (60, 4, random);
  for (std::size_t chunk : {std::size_t (1), std::size_t (50), std::size_t (333), std::size_t (1) << 18})
  {
    expectSameAsReference (three, chunk);
    expectSameAsReference (four, chunk);
    std::size_t at = 0;
    for (int line = 0; line < 60; ++line)
    {
      expectSameAsReference (three.substr (0, at) + "1 2 3 4\n" + three.substr (at), chunk);
      expectSameAsReference (three.substr (0, at) + "1 two 3\n" + three.substr (at), chunk);
      expectSameAsReference (three.substr (0, at) + four.substr (at), chunk);
      expectSameAsReference (three.substr (0, at) + "\n# a comment\n" + three.substr (at), chunk);
      at = three.find ('\n', at) + 1;
    }
  }
  // A cloud as large as a scan's: the same numbers, bit for bit.
  expectSameAsReference (numberLines (200000, 3, random), std::size_t (1) << 18);
}

TEST (XyzText, StreamReadInWindowsAgrees)
{
  // Windows shorter than a line, than a few lines and longer than the text; with the stream's
  // length known (room made ahead) and not.
  std::mt19937_64 random (13);
  const std::string three = numberLines (40, 3, random), four = numberLines (40, 4, random);
  std::vector<std::string> texts{three,
                                 three.substr (0, three.size () - 1),
                                 three + "1 2\n",
                                 "",
                                 "\n",
                                 "1 2 3",
                                 "# no number\n",
                                 three + std::string (3000, '5') + " 1 2\n" + three};
  std::size_t at = 0;
  for (int line = 0; line < 40; line += 3)
  {
    texts.push_back (three.substr (0, at) + "1 two 3\n" + three.substr (at));
    texts.push_back (three.substr (0, at) + four.substr (at));
    for (int skip = 0; skip < 3; ++skip)
      at = three.find ('\n', at) + 1;
  }
  for (const std::string& text : texts)
    for (std::size_t window :
         {std::size_t (1), std::size_t (7), std::size_t (64), std::size_t (1000), std::size_t (1) << 25})
      for (const std::size_t bytes : {text.size (), std::size_t (0)})
      {
        std::istringstream in (text);
        EXPECT_TRUE (sameXyzTables (apps::readXyzStream (in, bytes, window), referenceXyzTable (text)))
            << "window " << window << ", text '" << text.substr (0, 100) << "'";
      }
}

} // namespace
} // namespace pcl_wrap::test
