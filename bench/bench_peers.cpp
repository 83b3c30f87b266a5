// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// bench_peers METHOD SHAPE|FILE [N] [SEED] [--mesh OUT.obj] [--points OUT.xyz]: runs one method (see peers.h) on the
// points, in this process alone so that its peak memory is its own, and prints one JSON line:
// method, points, seconds (normals included), normal_seconds, peak_mib, vertices, triangles, note,
// stages (pcl_wrap's stage times; empty for the others).
// --points writes the input points first (for the Python peers). bench/compare.py runs it for
// every method and dataset.
#include "errors_reported.h"
#include "bench_points.h"
#include "peers.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <sys/resource.h>

static int
run (int argc, char** argv)
{
  if (argc < 3)
  {
    std::cerr << "usage: bench_peers METHOD SHAPE|FILE [N] [SEED] [--mesh OUT.obj]\nmethods:";
    for (const auto& [name, peer] : pcl_wrap::bench::peers ())
      std::cerr << ' ' << name;
    std::cerr << " cgal_alpha_wrap:diag/D:alpha/R cgal_alpha_wrap:spacing*S:alpha/R\n";
    return 2;
  }
  const std::string method = argv[1];
  std::string mesh_path, points_path;
  std::vector<std::string> positional;
  for (int i = 2; i < argc; ++i)
    if (std::string (argv[i]) == "--mesh" && i + 1 < argc)
      mesh_path = argv[++i];
    else if (std::string (argv[i]) == "--points" && i + 1 < argc)
      points_path = argv[++i];
    else
      positional.push_back (argv[i]);
  const std::size_t n = positional.size () > 1 ? std::stoul (positional[1]) : 0;
  const unsigned seed = positional.size () > 2 ? unsigned (std::stoul (positional[2])) : 1u;
  const auto& all = pcl_wrap::bench::peers ();
  const auto named = std::find_if (all.begin (), all.end (), [&] (const auto& p) { return p.first == method; });
  const std::optional<pcl_wrap::bench::Peer> peer =
      named != all.end () ? std::optional (named->second) : pcl_wrap::bench::alphaWrapAt (method);
  if (!peer)
  {
    std::cerr << "bench_peers: unknown method " << method << '\n';
    return 2;
  }
  const std::vector<pcl_wrap::Point3> points = pcl_wrap::bench::makePoints (positional[0], n, seed);
  if (!points_path.empty ())
  {
    std::ofstream xyz (points_path);
    xyz.precision (17);
    for (const auto& p : points)
      xyz << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }

  const auto start = std::chrono::steady_clock::now ();
  const pcl_wrap::bench::PeerOutput out = (*peer) (points);
  const double seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  rusage usage{};
  ::getrusage (RUSAGE_SELF, &usage);

  if (!mesh_path.empty ())
  {
    std::ofstream obj (mesh_path);
    if (!obj)
    {
      std::cerr << "bench_peers: cannot write " << mesh_path << '\n';
      return 1;
    }
    obj.precision (17);
    for (const auto& v : out.vertices)
      obj << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
    for (const auto& t : out.triangles)
      obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
  std::string stages;
  for (const auto& [stage, stage_seconds] : out.stages)
    stages += (stages.empty () ? "\"" : ",\"") + stage + "\":" + std::to_string (stage_seconds);
  std::printf ("{\"method\":\"%s\",\"points\":%zu,\"seconds\":%.6f,\"normal_seconds\":%.6f,\"peak_mib\":%.1f,"
               "\"vertices\":%zu,\"triangles\":%zu,\"note\":\"%s\",\"stages\":{%s}}\n",
               method.c_str (), points.size (), seconds, out.normal_seconds, usage.ru_maxrss / 1024.0,
               out.vertices.size (), out.triangles.size (), out.note.c_str (), stages.c_str ());
  return 0;
}

int
main (int argc, char** argv)
{
  return pcl_wrap::bench::errorsReported ("bench_peers", run, argc, argv);
}
