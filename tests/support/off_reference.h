// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "off_text.h"
#include "support/obj_reference.h"
#include "text_line.h"

#include <cmath>
#include <sstream>
#include <string>

namespace pcl_wrap::test
{

/** \brief What readOffStream() must give for \a text: one line after another with std::getline
  * and parseNumbers(), on one thread. */
inline apps::OffVertices
referenceOffVertices (const std::string& text)
{
  apps::OffVertices out;
  std::istringstream in (text);
  std::string line;
  std::vector<double> numbers;
  std::size_t number = 0;
  const auto fail = [&] (const std::string& problem) {
    out = {};
    out.error = problem;
    return out;
  };
  std::string problem;
  const auto next = [&] (const char* what) {
    while (std::getline (in, line))
    {
      ++number;
      if (!apps::parseNumbers (line, numbers))
      {
        problem = "line " + std::to_string (number) + ": not a number in " + what;
        return false;
      }
      if (!numbers.empty ())
        return true;
    }
    problem = std::string ("ends before ") + what;
    return false;
  };
  std::string header;
  while (header.empty () && std::getline (in, line))
  {
    ++number;
    std::istringstream (line.substr (0, line.find ('#'))) >> header;
  }
  if (header.size () < 3 || header.compare (header.size () - 3, 3, "OFF") != 0)
    return fail ("not an OFF file (no OFF header)");
  const std::string prefix = header.substr (0, header.size () - 3);
  out.normals = prefix.find ('N') != std::string::npos;
  out.colours = prefix.find ('C') != std::string::npos;
  out.needed = 3 + (out.normals ? 3 : 0) + (out.colours ? 3 : 0);
  std::istringstream rest (line.substr (line.find ("OFF") + 3));
  double count = 0;
  if (!(rest >> count))
  {
    if (!next ("the vertex count"))
      return fail (problem);
    count = numbers[0];
  }
  if (!(count >= 0 && count <= 4.0e9 && count == std::floor (count)))
    return fail ("bad vertex count");
  out.begin.assign (1, 0);
  for (std::size_t i = 0; i < static_cast<std::size_t> (count); ++i)
  {
    if (!next ("all vertices are read"))
      return fail (problem);
    if (numbers.size () < out.needed)
      return fail ("line " + std::to_string (number) + ": a vertex needs " + std::to_string (out.needed) + " numbers");
    out.values.insert (out.values.end (), numbers.begin (), numbers.end ());
    out.begin.push_back (out.values.size ());
  }
  return out;
}

/** \brief Do the two readings hold the same vertices, bit for bit, or the same error? */
inline bool
sameOffVertices (const apps::OffVertices& a, const apps::OffVertices& b)
{
  return a.error == b.error && a.normals == b.normals && a.colours == b.colours && a.needed == b.needed &&
         a.begin == b.begin && sameBits (a.values, b.values);
}

} // namespace pcl_wrap::test
