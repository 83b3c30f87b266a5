// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "text_line.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pcl_wrap::apps
{

bool
parseNumbers (const std::string& line, std::vector<double>& out)
{
  out.clear ();
  const std::string text = line.substr (0, line.find ('#'));
  std::istringstream tokens (text);
  std::string token;
  while (tokens >> token)
  {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod (token.c_str (), &end);
    if (end == token.c_str () || *end != '\0' || errno == ERANGE && std::abs (value) > 1.0)
      return false;
    out.push_back (value);
  }
  return true;
}

} // namespace pcl_wrap::apps
