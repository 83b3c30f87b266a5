// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_routing.h"

#include "message_exchange.h"

#include "delaunay/input_points.h"

#include <algorithm>
#include <limits>

namespace pcl_wrap::mpi
{
namespace
{

/** Sample points per tile that the cuts are drawn from. */
constexpr std::uint64_t SAMPLE_PER_TILE = 4096;

} // namespace

RoutedTile
routeToTiles (MPI_Comm comm, InputShare share)
{
  int ranks = 0;
  MPI_Comm_size (comm, &ranks);
  const std::uint64_t stride = std::max<std::uint64_t> (1, share.total / (SAMPLE_PER_TILE * ranks));
  std::vector<Point3> sample;
  for (const PointRecord& p : share.points)
    if (p.index % stride == 0)
      sample.push_back (p.position);
  const TilePartition partition (allGather (comm, sample), ranks);

  std::vector<std::vector<PointRecord>> outboxes (ranks);
  // The largest weight, and the smallest as a largest negated.
  double extremes[2] = {-std::numeric_limits<double>::infinity (), -std::numeric_limits<double>::infinity ()};
  for (PointRecord& p : share.points)
  {
    p.tile = partition.tileOf (p.position);
    extremes[0] = std::max (extremes[0], p.weight);
    extremes[1] = std::max (extremes[1], -p.weight);
    outboxes[p.tile].push_back (p);
  }
  share.points = {};
  RoutedTile out;
  double all[2];
  MPI_Allreduce (extremes, all, 2, MPI_DOUBLE, MPI_MAX, comm);
  out.w_max = std::max (all[0], 0.0);
  out.equal_weights = all[0] == -all[1];
  std::vector<PointRecord> points = allToAll (comm, outboxes);
  outboxes = {};

  // Points at one position are in one tile: keep one, as one process does.
  std::sort (points.begin (), points.end (), detail::keptBefore<PointRecord>);
  std::vector<PointRecord>& kept = out.points.points;
  for (const PointRecord& p : points)
    if (!kept.empty () && kept.back ().position == p.position)
      out.duplicates.push_back ({p.index, kept.back ().index});
    else
      kept.push_back (p);
  std::sort (kept.begin (), kept.end (), [] (const PointRecord& a, const PointRecord& b) { return a.index < b.index; });
  out.points.own = kept.size ();

  Box box;
  for (const PointRecord& p : kept)
    box.add (p.position);
  out.boxes = allGather (comm, std::vector<Box>{box});
  return out;
}

} // namespace pcl_wrap::mpi
