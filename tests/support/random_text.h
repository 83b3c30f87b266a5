// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <random>
#include <string>
#include <vector>

namespace pcl_wrap::test
{

/** \brief 0 to \a most tokens drawn from \a tokens (which may hold NUL bytes) and written one after
  * another: text for a file reader to take apart as its line-by-line reference does. */
inline std::string
randomTokenText (std::mt19937_64& random, const std::vector<std::string>& tokens, int most = 60)
{
  std::string text;
  const int length = std::uniform_int_distribution<int> (0, most) (random);
  for (int i = 0; i < length; ++i)
    text += tokens[random () % tokens.size ()];
  return text;
}

} // namespace pcl_wrap::test
