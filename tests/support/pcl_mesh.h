// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// PCL meshes as the triangles the topology checks take.
#include "topology.h"

#include <pcl/Vertices.h>

#include <gtest/gtest.h>

#include <vector>

namespace pcl_wrap::test
{

/** The polygons as triangles; a polygon with other than three vertices fails the test. */
inline std::vector<Triangle>
trianglesOf (const std::vector<pcl::Vertices>& polygons)
{
  std::vector<Triangle> triangles;
  for (const auto& polygon : polygons)
  {
    EXPECT_EQ (polygon.vertices.size (), 3u);
    if (polygon.vertices.size () == 3)
      triangles.push_back ({std::uint32_t (polygon.vertices[0]), std::uint32_t (polygon.vertices[1]),
                            std::uint32_t (polygon.vertices[2])});
  }
  return triangles;
}

} // namespace pcl_wrap::test
