// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap_pipeline IN.pcd OUT.ply [--voxel LEAF] [--outliers K STDDEV] [--radius-rel R]
//
// A PCL pipeline with pcl_wrap as a drop-in stage: load a PCD, thin it with a VoxelGrid and/or
// drop outliers with a StatisticalOutlierRemoval, wrap it, save the mesh as PLY. An organised
// cloud (a depth camera's, NaNs where nothing was seen) goes through the same path.
#include <pcl_wrap/wrap.h>

#include <pcl/filters/statistical_outlier_removal.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <cstdlib>
#include <iostream>
#include <string>

int
main (int argc, char** argv)
{
  if (argc < 3)
  {
    std::cerr << "usage: pcl_wrap_pipeline IN.pcd OUT.ply [--voxel LEAF] [--outliers K STDDEV] [--radius-rel R]\n";
    return 2;
  }
  using Cloud = pcl::PointCloud<pcl::PointXYZ>;
  auto cloud = pcl::make_shared<Cloud> ();
  if (pcl::io::loadPCDFile (argv[1], *cloud) < 0)
    return 1; // PCL has said why

  pcl_wrap::Wrap<pcl::PointXYZ> wrap;
  for (int i = 3; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (option == "--voxel" && i + 1 < argc)
    {
      pcl::VoxelGrid<pcl::PointXYZ> grid;
      const float leaf = std::strtof (argv[++i], nullptr);
      grid.setLeafSize (leaf, leaf, leaf);
      grid.setInputCloud (cloud);
      auto thinned = pcl::make_shared<Cloud> ();
      grid.filter (*thinned);
      cloud = thinned;
    }
    else if (option == "--outliers" && i + 2 < argc)
    {
      pcl::StatisticalOutlierRemoval<pcl::PointXYZ> outliers;
      outliers.setMeanK (std::atoi (argv[++i]));
      outliers.setStddevMulThresh (std::strtod (argv[++i], nullptr));
      outliers.setKeepOrganized (true); // an organised cloud stays organised, outliers become NaN
      outliers.setInputCloud (cloud);
      auto kept = pcl::make_shared<Cloud> ();
      outliers.filter (*kept);
      cloud = kept;
    }
    else if (option == "--radius-rel" && i + 1 < argc)
      wrap.setRelativeRadius (std::strtod (argv[++i], nullptr));
    else
    {
      std::cerr << "pcl_wrap_pipeline: unknown option " << option << '\n';
      return 2;
    }
  }

  wrap.setInputCloud (cloud); // NaNs are skipped; the mesh's cloud is this cloud
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  if (mesh.polygons.empty ())
  {
    std::cerr << "pcl_wrap_pipeline: no surface from " << cloud->size () << " points\n";
    return 1;
  }
  if (pcl::io::savePLYFileBinary (argv[2], mesh) < 0)
    return 1;
  const auto& stats = wrap.getStatistics ();
  std::cout << stats.points_input << " points (" << stats.points_skipped << " without coordinates), "
            << mesh.polygons.size () << " triangles, " << stats.total_seconds << " s\n";
  return 0;
}
