// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/wrap_result.h>

#include <pcl/PCLPointCloud2.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_wrap
{

/** \brief Appends to \a cloud a copy of each of its points \a copies (WrapResult::copies, made
  * where the surface was split), with every field: the points then stand in one block (rows a
  * message pads are packed) and the cloud is no longer organised. Nothing changes without copies. */
inline void
appendCopies (pcl::PCLPointCloud2& cloud, const std::vector<PointIndex>& copies)
{
  if (copies.empty ())
    return;
  const std::size_t step = cloud.point_step, n = std::size_t (cloud.width) * cloud.height;
  if (cloud.row_step != cloud.width * step)
  {
    std::vector<std::uint8_t> packed (n * step);
    for (std::size_t row = 0; row < cloud.height; ++row)
      std::copy_n (cloud.data.begin () + row * cloud.row_step, cloud.width * step,
                   packed.begin () + row * cloud.width * step);
    cloud.data = std::move (packed);
  }
  cloud.data.resize ((n + copies.size ()) * step);
  for (std::size_t k = 0; k < copies.size (); ++k)
    std::copy_n (cloud.data.begin () + copies[k] * step, step, cloud.data.begin () + (n + k) * step);
  cloud.width = static_cast<std::uint32_t> (n + copies.size ());
  cloud.height = 1;
  cloud.row_step = static_cast<std::uint32_t> (cloud.width * step);
}

} // namespace pcl_wrap
