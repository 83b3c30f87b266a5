// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "pcd_ascii.h"

#include "ascii_rows.h"

#include <pcl/common/io.h>

#include <vector>

namespace pcl_wrap::apps
{

std::string
readPcdAsciiData (std::istream& in, std::uintmax_t bytes, pcl::PCLPointCloud2& cloud, std::size_t window_bytes,
                  std::size_t chunk_bytes)
{
  std::vector<RowValue> values;
  for (const pcl::PCLPointField& f : cloud.fields)
    for (std::uint32_t c = 0; c < f.count; ++c)
      values.push_back ({f.name, f.datatype, f.datatype,
                         f.offset + c * static_cast<std::uint32_t> (pcl::getFieldSize (f.datatype)), f.name == "_"});
  cloud.is_dense = false; // not looked at: NaN values are allowed
  return readAsciiRows (in, bytes, values, cloud.point_step, std::size_t (cloud.width) * cloud.height, false,
                        cloud.data, window_bytes, chunk_bytes);
}

} // namespace pcl_wrap::apps
