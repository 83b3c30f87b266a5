// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "text_line.h"
#include "xyz_text.h"

#include <cstring>
#include <sstream>
#include <string>

namespace pcl_wrap::test
{

/** \brief What parseXyzText() must give for \a text: one line after another with std::getline
  * and parseNumbers(), on one thread. */
inline apps::XyzTable
referenceXyzTable (const std::string& text)
{
  apps::XyzTable table;
  std::istringstream in (text);
  std::string line;
  std::vector<double> numbers;
  for (std::size_t number = 1; std::getline (in, line); ++number)
  {
    const std::string at = "line " + std::to_string (number) + ": ";
    if (!apps::parseNumbers (line, numbers))
      table.error = at + "not a number";
    else if (numbers.empty ())
      continue;
    else if (numbers.size () < 3)
      table.error = at + "expected at least 3 numbers (x y z ...), found " + std::to_string (numbers.size ());
    else if (table.columns != 0 && numbers.size () != table.columns)
      table.error =
          at + std::to_string (numbers.size ()) + " numbers where earlier lines have " + std::to_string (table.columns);
    if (!table.error.empty ())
    {
      table.values.clear ();
      table.columns = 0;
      return table;
    }
    table.columns = numbers.size ();
    table.values.insert (table.values.end (), numbers.begin (), numbers.end ());
  }
  return table;
}

/** \brief Do the two tables hold the same numbers, bit for bit (NaNs too), or the same error? */
inline bool
sameXyzTables (const apps::XyzTable& a, const apps::XyzTable& b)
{
  return a.error == b.error && a.columns == b.columns && a.values.size () == b.values.size () &&
         (a.values.empty () ||
          std::memcmp (a.values.data (), b.values.data (), a.values.size () * sizeof (double)) == 0);
}

} // namespace pcl_wrap::test
