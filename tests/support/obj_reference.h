// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "obj_text.h"
#include "text_line.h"

#include <cstring>
#include <sstream>
#include <string>

namespace pcl_wrap::test
{

/** \brief What parseObjText() must give for \a text: one line after another with std::getline
  * and parseNumbers(), on one thread. */
inline apps::ObjVertices
referenceObjVertices (const std::string& text)
{
  apps::ObjVertices read;
  std::istringstream in (text);
  std::string line;
  std::vector<double> numbers;
  for (std::size_t number = 1; std::getline (in, line); ++number)
  {
    const std::size_t start = line.find_first_not_of (" \t");
    const std::size_t end = line.find_first_of (" \t", start);
    if (start == std::string::npos || end == std::string::npos)
      continue;
    const std::string keyword = line.substr (start, end - start);
    const std::string at = "line " + std::to_string (number) + ": ";
    if (keyword == "vn")
    {
      if (!apps::parseNumbers (line.substr (end), numbers) || numbers.size () != 3)
      {
        read = {};
        read.error = at + "a normal needs 3 numbers";
        return read;
      }
      read.normals.insert (read.normals.end (), {float (numbers[0]), float (numbers[1]), float (numbers[2])});
      continue;
    }
    if (keyword != "v")
      continue;
    if (!apps::parseNumbers (line.substr (end), numbers) || numbers.size () < 3 || numbers.size () > 7)
    {
      read = {};
      read.error = at + "a vertex needs 3 coordinates";
      return read;
    }
    read.points.insert (read.points.end (), numbers.begin (), numbers.begin () + 3);
    read.every_vertex_coloured = read.every_vertex_coloured && numbers.size () == 6;
    if (read.every_vertex_coloured)
      read.colours.insert (read.colours.end (), numbers.begin () + 3, numbers.end ());
  }
  if (!read.every_vertex_coloured)
    read.colours.clear ();
  return read;
}

/** \brief Are \a a and \a b the same bit for bit (NaNs too)? */
template <class T>
bool
sameBits (const std::vector<T>& a, const std::vector<T>& b)
{
  return a.size () == b.size () && (a.empty () || std::memcmp (a.data (), b.data (), a.size () * sizeof (T)) == 0);
}

/** \brief Do the two readings hold the same vertices, colours and normals, or the same error? */
inline bool
sameObjVertices (const apps::ObjVertices& a, const apps::ObjVertices& b)
{
  return a.error == b.error && a.every_vertex_coloured == b.every_vertex_coloured && sameBits (a.points, b.points) &&
         sameBits (a.colours, b.colours) && sameBits (a.normals, b.normals);
}

} // namespace pcl_wrap::test
