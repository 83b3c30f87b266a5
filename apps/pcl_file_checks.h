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

/** \brief What checkPlyHeader() found in a PLY file's header. */
struct PlyHeaderCheck
{
  std::optional<std::uint64_t> ascii_start; ///< where the data starts if it is ASCII
  std::uint64_t points = 0; ///< the points PCL's reader is to give: the range grid's cells, else the vertices
  /** Why PCL's reader would give a cloud of another size, if it would: obj_info's num_cols x
    * num_rows, which it takes for the cloud's size, is not \a points. Empty if not. */
  std::string size_problem;
};

/** \brief PCL's PLY reader allocates what the header declares before reading the data (2e9
  * vertices cost 23 GB): the declared elements checked to fit in the file, and the header checked
  * for what makes the reader fail an assertion.
  * \throws FileError where the header is malformed */
PlyHeaderCheck
checkPlyHeader (const std::string& path);

/** \brief PCL's ASCII PLY reader turns a token that is not a number into NaN, silently: every
  * token of the data from \a start (checkPlyHeader()) on checked to be a number.
  * \throws FileError where one is not */
void
checkPlyAsciiData (const std::string& path, std::uint64_t start);

} // namespace pcl_wrap::apps
