// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// A point type of the user's own, compiled from the template definitions (PCL_NO_PRECOMPILE).
#define PCL_NO_PRECOMPILE
#include <pcl_wrap/wrap.h>

#include <pcl/point_types.h>
#include <pcl/register_point_struct.h>

#include <gtest/gtest.h>

#include <cmath>

namespace scanner
{
struct EIGEN_ALIGN16 Return
{
  PCL_ADD_POINT4D;
  float range;
  std::uint16_t ring;
  PCL_MAKE_ALIGNED_OPERATOR_NEW
};
} // namespace scanner

POINT_CLOUD_REGISTER_POINT_STRUCT (scanner::Return,
                                   (float, x, x) (float, y, y) (float, z, z) (float, range, range) (std::uint16_t, ring,
                                                                                                    ring))

TEST (PclWrap, CustomPointTypeWithoutPrecompiledInstantiation)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<scanner::Return>> ();
  // A regular octahedron: 6 points, 8 triangles, all of them on W.
  const float v[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const auto& p : v)
  {
    scanner::Return r;
    r.x = p[0] * 1.01f, r.y = p[1] * 0.99f, r.z = p[2]; // a little off regular: no ties
    r.range = 1, r.ring = 0;
    cloud->push_back (r);
  }
  pcl_wrap::Wrap<scanner::Return> wrap;
  wrap.setInputCloud (cloud);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  EXPECT_EQ (mesh.polygons.size (), 8u);
}
