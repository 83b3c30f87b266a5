// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_spacing.h"

#include "message_exchange.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace pcl_wrap::mpi
{
namespace
{

std::uint64_t
bitsOf (double value)
{
  std::uint64_t bits = 0;
  std::memcpy (&bits, &value, sizeof bits);
  return bits;
}

double
valueOf (std::uint64_t bits)
{
  double value = 0;
  std::memcpy (&value, &bits, sizeof value);
  return value;
}

} // namespace

double
tileMedianSpacing (MPI_Comm comm, const TileComplex& tile)
{
  const detail::SimplicialComplex& complex = tile.complex ();
  const std::vector<Point3>& p = tile.positions ();
  constexpr double NONE = std::numeric_limits<double>::infinity ();
  std::vector<double> nearest (complex.numVertices (), NONE); // squared, as spacing.cpp computes it
  for (detail::SimplexId e = 0; complex.dimension () >= 1 && e < complex.size (1); ++e)
  {
    const std::uint32_t* v = complex.vertices (1, e);
    const Point3 &a = p[v[0]], &b = p[v[1]];
    const double squared =
        (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
    nearest[v[0]] = std::min (nearest[v[0]], squared);
    nearest[v[1]] = std::min (nearest[v[1]], squared);
  }
  std::vector<double> own;
  for (std::uint32_t v = 0; v < nearest.size (); ++v)
    if (nearest[v] != NONE && tile.belongsHere ({0, v}))
      own.push_back (nearest[v]);
  std::sort (own.begin (), own.end ());
  const std::uint64_t total = sumOverRanks (comm, own.size ());
  if (total == 0)
    return 0.0;
  // The value at index total / 2 of all of them in order, as one process's nth_element takes it:
  // the smallest whose count of values at most it exceeds that index.
  const std::uint64_t index = total / 2;
  std::uint64_t low = 0, high = bitsOf (NONE);
  while (low < high)
  {
    const std::uint64_t middle = low + (high - low) / 2;
    const auto at_most =
        static_cast<std::uint64_t> (std::upper_bound (own.begin (), own.end (), valueOf (middle)) - own.begin ());
    if (sumOverRanks (comm, at_most) > index)
      high = middle;
    else
      low = middle + 1;
  }
  return std::sqrt (valueOf (low));
}

} // namespace pcl_wrap::mpi
