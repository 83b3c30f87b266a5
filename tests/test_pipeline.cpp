// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// examples/pipeline, run as a user runs it: PCD -> VoxelGrid or StatisticalOutlierRemoval ->
// pcl_wrap -> PLY, on a real scan and on an organised cloud with NaNs; its mesh equals the
// library's on the same filtered cloud.
#include "point_file.h"
#include "support/pcl_mesh.h"

#include <pcl_wrap/wrap.h>

#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace pcl_wrap::test
{
namespace
{

using Cloud = pcl::PointCloud<pcl::PointXYZ>;
const std::string DIR = ::testing::TempDir ();

pcl::PolygonMesh
runPipeline (const Cloud& cloud, const std::string& name, const std::string& options)
{
  const std::string in = DIR + name + ".pcd", out = DIR + name + ".ply";
  EXPECT_EQ (pcl::io::savePCDFileBinary (in, cloud), 0);
  EXPECT_EQ (std::system (
                 (std::string (PCL_WRAP_PIPELINE) + " " + in + " " + out + " " + options + " > /dev/null").c_str ()),
             0);
  pcl::PolygonMesh mesh;
  EXPECT_GE (pcl::io::loadPLYFile (out, mesh), 0);
  return mesh;
}

std::size_t
libraryTriangles (const Cloud::Ptr& cloud)
{
  Wrap<pcl::PointXYZ> wrap;
  wrap.setInputCloud (cloud);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  return mesh.polygons.size ();
}

TEST (Pipeline, ScanThroughVoxelGridToPly)
{
  auto bunny = pcl::make_shared<Cloud> ();
  for (const auto& p : apps::readPointFile (std::string (PCL_WRAP_DATA_DIR) + "/bunny00.off").points)
    bunny->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  const pcl::PolygonMesh mesh = runPipeline (*bunny, "pipeline_bunny", "--voxel 0.003");

  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setLeafSize (0.003f, 0.003f, 0.003f);
  grid.setInputCloud (bunny);
  auto thinned = pcl::make_shared<Cloud> ();
  grid.filter (*thinned);
  ASSERT_LT (thinned->size (), bunny->size ());
  EXPECT_EQ (std::size_t (mesh.cloud.width) * mesh.cloud.height, thinned->size ());
  EXPECT_EQ (mesh.polygons.size (), libraryTriangles (thinned));
  const SurfaceReport s = describeSurface (trianglesOf (mesh.polygons));
  EXPECT_TRUE (s.closed_manifold);
  EXPECT_EQ (s.components, 1u);
  EXPECT_EQ (s.euler, 2) << "the bunny stays a sphere";
}

TEST (Pipeline, OrganisedCloudWithNansThroughOutlierRemoval)
{
  // A depth camera's view of a bumpy surface, with holes, a few stray points in front of it.
  auto cloud = pcl::make_shared<Cloud> (64, 48);
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  for (std::uint32_t r = 0; r < cloud->height; ++r)
    for (std::uint32_t c = 0; c < cloud->width; ++c)
    {
      const float x = (float (c) - 32.f) / 32.f, y = (float (r) - 24.f) / 32.f;
      const bool seen = x * x + y * y < 0.8f && (r * 7 + c * 3) % 11 != 0;
      const bool stray = (r * 31 + c * 17) % 97 == 0;
      cloud->at (c, r) = !seen
                             ? pcl::PointXYZ (nan, nan, nan)
                             : pcl::PointXYZ (x, y, (stray ? 1.2f : 2.f) + 0.1f * std::sin (4 * x) * std::cos (3 * y));
    }
  cloud->is_dense = false;
  const pcl::PolygonMesh mesh = runPipeline (*cloud, "pipeline_depth", "--outliers 8 1.0");

  pcl::StatisticalOutlierRemoval<pcl::PointXYZ> outliers;
  outliers.setMeanK (8);
  outliers.setStddevMulThresh (1.0);
  outliers.setKeepOrganized (true);
  outliers.setInputCloud (cloud);
  auto kept = pcl::make_shared<Cloud> ();
  outliers.filter (*kept);
  // Every pixel keeps its index; points the surface copied to split a pinch follow them.
  Cloud out;
  pcl::fromPCLPointCloud2 (mesh.cloud, out);
  ASSERT_GE (out.size (), cloud->size ());
  for (std::size_t i = 0; i < kept->size (); ++i)
    if (std::isfinite ((*kept)[i].z))
      EXPECT_EQ ((*kept)[i].z, out[i].z) << "pixel " << i;
    else
      EXPECT_FALSE (std::isfinite (out[i].z)) << "pixel " << i;
  ASSERT_FALSE (mesh.polygons.empty ());
  EXPECT_EQ (mesh.polygons.size (), libraryTriangles (kept));
  for (const auto& p : mesh.polygons)
    for (const auto v : p.vertices)
    {
      const pcl::PointXYZ& q = v < kept->size () ? (*kept)[v] : out[v];
      ASSERT_TRUE (std::isfinite (q.z)) << "a triangle uses a NaN or removed point";
      EXPECT_GT (q.z, 1.5f) << "a stray point survived the outlier removal";
    }
}

} // namespace
} // namespace pcl_wrap::test
