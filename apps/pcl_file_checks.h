// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The guards that stand before PCL's PCD and PLY readers: each throws FileError on a file the
// reader would mishandle.
#include <cstdint>
#include <optional>
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
  * vertices cost 23 GB): the declared elements checked to fit in the file. Returns where the data
  * starts if it is ASCII, else nothing.
  * \throws FileError where the header is malformed */
std::optional<std::uint64_t>
checkPlyHeader (const std::string& path);

/** \brief PCL's ASCII PLY reader turns a token that is not a number into NaN, silently: every
  * token of the data from \a start (checkPlyHeader()) on checked to be a number.
  * \throws FileError where one is not */
void
checkPlyAsciiData (const std::string& path, std::uint64_t start);

} // namespace pcl_wrap::apps
