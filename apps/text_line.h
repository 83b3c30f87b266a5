// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief The whitespace-separated numbers of one line, after a '#' comment is cut off; false when a
  * token is not a number. "nan" and "inf" are numbers (such points are skipped, not rejected). */
bool
parseNumbers (const std::string& line, std::vector<double>& out);

} // namespace pcl_wrap::apps
