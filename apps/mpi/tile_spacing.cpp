// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_spacing.h"

#include "message_exchange.h"

#include "delaunay/spacing.h"

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
  // Each tile's own points have their whole stars here, so their nearest neighbours among their
  // edges are those of Del S, measured as one process measures them.
  const detail::SimplicialComplex& complex = tile.complex ();
  constexpr double NONE = std::numeric_limits<double>::infinity ();
  const std::vector<double> nearest =
      detail::nearestNeighbourSquared (complex.vertices (1, 0), complex.size (1), 1, tile.positions ());
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
