// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The check that every token of a text is a number, which stands before PCL's ASCII PLY reader,
// against reading the text line by line with parseNumbers(): the same first failing line, on edge
// cases and random texts with a bad token at each place, read in windows and tasks of a few bytes
// and more.
#include "text_line.h"
#include "text_pieces.h"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

namespace pcl_wrap::test
{
namespace
{

std::size_t
referenceFirstLineNotNumbers (const std::string& text)
{
  std::istringstream in (text);
  std::vector<double> numbers;
  std::string line;
  for (std::size_t number = 0; std::getline (in, line); ++number)
    if (!apps::parseNumbers (line, numbers))
      return number;
  return apps::NO_LINE;
}

void
expectSameAsReference (const std::string& text)
{
  const std::size_t expected = referenceFirstLineNotNumbers (text);
  for (std::size_t window : {std::size_t (1), std::size_t (7), std::size_t (64), std::size_t (1) << 25})
    for (std::size_t chunk : {std::size_t (1), std::size_t (3), std::size_t (50), std::size_t (1) << 18})
    {
      std::istringstream in (text);
      EXPECT_EQ (apps::firstLineNotNumbers (in, window % 2 ? text.size () : 0, window, chunk), expected)
          << "windows of " << window << ", tasks of " << chunk << ": '" << text.substr (0, 200) << "'";
    }
}

TEST (TextPieces, FirstLineNotNumbersAsLineByLine)
{
  for (const char* text : {"", "\n", "x", "1 2 3", "1 2 3\n", "1 2\nx\n", "\n\n\nx", "1 # x\n2\n", "# x\n1 y\n",
                           "1\r\n2\r\n+3 -.5e1 inf nan 0x1p3\n", "1 2 3\n4 5 6", "1 2 3\n4 5 6x", "1\n\t\n 2 \n3 4,\n"})
    expectSameAsReference (text);
  std::mt19937_64 random (3);
  std::uniform_real_distribution<double> value (-1e3, 1e3);
  std::string text;
  char number[40];
  for (int line = 0; line < 300; ++line)
  {
    for (int k = 0; k < 1 + line % 4; ++k)
    {
      std::snprintf (number, sizeof number, "%.17g ", value (random));
      text += number;
    }
    text += line % 17 == 0 ? "\n\n" : "\n";
  }
  expectSameAsReference (text);
  for (std::size_t at : {std::size_t (0), text.size () / 3, text.size () - 2})
  {
    std::string bad = text;
    bad[at] = 'q';
    expectSameAsReference (bad);
  }
}

} // namespace
} // namespace pcl_wrap::test
