// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "surface/solid_labelling.h"

#include <cstddef>
#include <random>

namespace pcl_wrap::test
{

/** Labels of \a n tetrahedra, each inside with a chance of \a percent in 100, every margin 1: a
  * solid with parts and voids of every size. */
inline detail::SolidLabels
randomLabels (std::size_t n, unsigned percent, std::mt19937& random)
{
  detail::SolidLabels labels;
  for (std::size_t t = 0; t < n; ++t)
  {
    labels.inside.push_back (random () % 100 < percent);
    labels.margin.push_back (1.0f);
  }
  return labels;
}

} // namespace pcl_wrap::test
