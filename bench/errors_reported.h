// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <exception>
#include <iostream>

namespace pcl_wrap::bench
{

/** \brief A tool's main: \a run (argc, argv), with an exception it throws (an unreadable or
  * malformed file) reported as "NAME: what" and exit status 1, where it would abort the process. */
inline int
errorsReported (const char* name, int (*run) (int, char**), int argc, char** argv)
{
  try
  {
    return run (argc, argv);
  }
  catch (const std::exception& e)
  {
    std::cerr << name << ": " << e.what () << '\n';
    return 1;
  }
}

} // namespace pcl_wrap::bench
