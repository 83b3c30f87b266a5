// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// bench_weights FILE [C ...]: what weights from local spacing change on a real scan. Each point's
// spacing is the distance to its nearest neighbour (PCL's FLANN k-d tree); its weight is
// (C * spacing)^2. Prints, per C, the triangles of W, the share of the points on W, the hidden
// points and the time.
#include "errors_reported.h"
#include "point_file.h"

#include <pcl_wrap/compute_wrap.h>

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

static int
run (int argc, char** argv)
{
  if (argc < 2)
  {
    std::fprintf (stderr, "usage: bench_weights FILE [C ...]\n");
    return 2;
  }
  const std::vector<pcl_wrap::Point3> points = pcl_wrap::apps::readPoints (argv[1]);
  std::vector<double> factors;
  for (int i = 2; i < argc; ++i)
    factors.push_back (std::stod (argv[i]));
  if (factors.empty ())
    factors = {0.0, 0.25, 0.5, 0.75, 1.0};

  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (const auto& p : points)
    cloud->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  std::vector<double> spacing (points.size ());
  pcl::Indices neighbours (2);
  std::vector<float> squared (2);
  for (std::size_t i = 0; i < points.size (); ++i)
    spacing[i] = tree.nearestKSearch ((*cloud)[i], 2, neighbours, squared) == 2 ? std::sqrt (double (squared[1])) : 0.0;

  std::printf ("%s: %zu points\n%6s %12s %12s %10s %10s\n", argv[1], points.size (), "C", "W triangles",
               "points on W", "hidden", "seconds");
  for (double c : factors)
  {
    std::vector<double> weights (points.size ());
    for (std::size_t i = 0; i < points.size (); ++i)
      weights[i] = (c * spacing[i]) * (c * spacing[i]);
    const pcl_wrap::WrapResult r = pcl_wrap::computeWrap (points, weights);
    std::set<pcl_wrap::PointIndex> on_w;
    for (const auto& t : r.surface.triangles)
      on_w.insert (t.begin (), t.end ());
    std::printf ("%6.2f %12zu %11.1f%% %10zu %10.3f\n", c, r.surface.triangles.size (),
                 100.0 * on_w.size () / points.size (), r.statistics.points_hidden, r.statistics.total_seconds);
  }
  return 0;
}

int
main (int argc, char** argv)
{
  return pcl_wrap::bench::errorsReported ("bench_weights", run, argc, argv);
}
