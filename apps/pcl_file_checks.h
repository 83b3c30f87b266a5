// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The guards that stand before PCL's PCD and PLY readers: each throws FileError on a file the
// reader would mishandle.
#include <string>

namespace pcl_wrap::apps
{

/** \brief PCL's PCD reader trusts the header and corrupts memory on a malformed one (found by
  * fuzzing): the header checked strictly, and the size of binary data it declares against the
  * file (ASCII data is checked as it is read: readPcdAsciiData()).
  * \throws FileError where the file is malformed */
void
checkPcdFile (const std::string& path);

/** \brief PCL's PLY reader allocates what the header declares before reading the data (2e9
  * vertices cost 23 GB): the declared elements checked to fit in the file. Returns whether the
  * data is ASCII.
  * \throws FileError where the header is malformed */
bool
checkPlyHeader (const std::string& path);

/** \brief checkPlyHeader(), and for ASCII data, every token of it checked to be a number: PCL's
  * reader turns one that is not into NaN.
  * \throws FileError where the file is malformed */
void
checkPlyFile (const std::string& path);

} // namespace pcl_wrap::apps
