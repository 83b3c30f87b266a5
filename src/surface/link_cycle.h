// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Do the edges [first, last) (pairs of vertex ids) make one cycle, each vertex on it in
  * exactly two of them? A vertex of a closed 2-manifold has such a link: the edges opposite it in
  * its triangles. */
template <class It>
bool
isOneCycle (It first, It last)
{
  const auto k = static_cast<std::size_t> (last - first);
  if (k < 3)
    return false;
  // (end, edge) for both ends of every edge, sorted: a cycle has each end exactly twice.
  constexpr std::size_t ON_STACK = 64;
  std::array<std::pair<std::uint32_t, std::uint32_t>, ON_STACK> small;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> large;
  std::pair<std::uint32_t, std::uint32_t>* ends = small.data ();
  if (2 * k > ON_STACK)
  {
    large.resize (2 * k);
    ends = large.data ();
  }
  for (std::size_t e = 0; e < k; ++e)
  {
    ends[2 * e] = {first[e][0], static_cast<std::uint32_t> (e)};
    ends[2 * e + 1] = {first[e][1], static_cast<std::uint32_t> (e)};
  }
  std::sort (ends, ends + 2 * k);
  for (std::size_t a = 0; a < 2 * k; a += 2)
    if (ends[a].first != ends[a + 1].first || (a + 2 < 2 * k && ends[a + 2].first == ends[a].first))
      return false;
  // Walk from edge 0 until back at its first end: one cycle if that took every edge.
  const auto other_edge = [&] (std::uint32_t end, std::uint32_t edge) {
    const auto* at = std::lower_bound (ends, ends + 2 * k, std::make_pair (end, std::uint32_t (0)));
    return at[0].second == edge ? at[1].second : at[0].second;
  };
  std::uint32_t edge = 0, end = first[0][1];
  std::size_t steps = 1;
  while (end != first[0][0])
  {
    edge = other_edge (end, edge);
    end = first[edge][0] == end ? first[edge][1] : first[edge][0];
    ++steps;
  }
  return steps == k;
}

} // namespace pcl_wrap::detail
