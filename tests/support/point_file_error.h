// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "point_file.h"

#include <string>

namespace pcl_wrap::test
{

/** \brief What the command-line tool's reader says of the file at \a path: its error, or nothing
  * where it reads the file. */
inline std::string
pointFileError (const std::string& path)
{
  try
  {
    apps::readPointFile (path);
    return "";
  }
  catch (const apps::FileError& e)
  {
    return e.what ();
  }
}

} // namespace pcl_wrap::test
