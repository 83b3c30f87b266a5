// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "off_text.h"
#include "support/obj_reference.h"

#include <sstream>
#include <string>

namespace pcl_wrap::test
{

/** \brief What readOffStream() must give for \a text: its header as readOffHeader() reads it,
  * then one vertex line after another with nextNumbersLine(), on one thread. */
inline apps::OffVertices
referenceOffVertices (const std::string& text)
{
  apps::OffVertices out;
  std::istringstream in (text);
  const auto fail = [&] (const std::string& problem) {
    out = {};
    out.error = problem;
    return out;
  };
  const apps::OffHeader header = apps::readOffHeader (in);
  if (!header.error.empty ())
    return fail (header.error);
  out.normals = header.normals;
  out.colours = header.colours;
  out.needed = header.needed;
  std::size_t lines = header.lines;
  std::vector<double> numbers;
  std::string problem;
  out.begin.assign (1, 0);
  for (std::size_t i = 0; i < header.vertices; ++i)
  {
    if (!apps::nextNumbersLine (in, numbers, lines, "all vertices are read", problem))
      return fail (problem);
    if (numbers.size () < out.needed)
      return fail ("line " + std::to_string (lines) + ": a vertex needs " + std::to_string (out.needed) + " numbers");
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
