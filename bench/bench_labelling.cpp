// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// bench_labelling SHAPE N [RUNS]: the default surface's labelling on its own (docs/surface.md §1),
// on the Delaunay triangulation of N points (SHAPE as bench_wrap takes it, or a point file): the
// votes, on all threads, and the priority flood, on the calling thread, RUNS times on the same
// triangulation, each time and the median. In the command the flood runs beside the complex stage;
// here it runs alone, so a change to the flood can be timed without the stages around it.
#include "bench_points.h"

#include "delaunay/regular_triangulation.h"
#include "delaunay/tetrahedra.h"
#include "surface/solid_labelling.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace
{

double
secondsSince (std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
}

double
median (std::vector<double> values)
{
  std::sort (values.begin (), values.end ());
  return values[values.size () / 2];
}

} // namespace

int
main (int argc, char** argv)
try
{
  using namespace pcl_wrap::detail;
  if (argc < 3 || argc > 4)
  {
    std::fprintf (stderr, "usage: bench_labelling SHAPE N [RUNS]\n");
    return 2;
  }
  const int runs = argc > 3 ? std::max (1, std::stoi (argv[3])) : 5;
  const std::vector<pcl_wrap::Point3> points = pcl_wrap::bench::makePoints (argv[1], std::stoul (argv[2]), 1);
  const std::vector<double> weights (points.size (), 0.0);
  Triangulation triangulation = triangulate (points, weights);
  if (triangulation.dimension != 3)
  {
    std::fprintf (stderr, "bench_labelling: the points span no volume\n");
    return 1;
  }
  std::vector<pcl_wrap::Point3> positions (triangulation.point_of_vertex.size ());
  for (std::size_t v = 0; v < positions.size (); ++v)
    positions[v] = points[triangulation.point_of_vertex[v]];
  const std::vector<double> vertex_weights (positions.size (), 0.0);
  const Tetrahedra adjacency (std::move (triangulation.neighbours));
  std::printf ("%s, %zu points, %zu tetrahedra\n", argv[1], points.size (), adjacency.size ());
  std::vector<double> votes, flood;
  for (int run = 0; run < runs; ++run)
  {
    const auto start = std::chrono::steady_clock::now ();
    SolidLabelling labelling (triangulation.top_simplices, adjacency, positions, vertex_weights);
    votes.push_back (secondsSince (start));
    const auto flooding = std::chrono::steady_clock::now ();
    labelling.flood ();
    flood.push_back (secondsSince (flooding));
    std::printf ("  run %d: votes %.3f s, flood %.3f s\n", run + 1, votes.back (), flood.back ());
  }
  std::printf ("median: votes %.3f s (all threads), flood %.3f s (one thread)\n", median (votes), median (flood));
  return 0;
}
catch (const std::exception& e)
{
  std::fprintf (stderr, "bench_labelling: %s\n", e.what ());
  return 1;
}
