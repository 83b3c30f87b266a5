// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The surface stage's test of a vertex's link (docs/surface.md §2) against a graph search.
#include "surface/link_cycle.h"
#include "support/topology.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

using Edge = std::array<std::uint32_t, 2>;

bool
byGraphSearch (const std::vector<Edge>& edges)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (const auto& e : edges)
    pairs.emplace_back (e[0], e[1]);
  return isOneCycle (pairs);
}

bool
byTheEngine (const std::vector<Edge>& edges)
{
  return detail::isOneCycle (edges.begin (), edges.end ());
}

/** A cycle through \a n vertices with ids from \a first, in steps of \a step, edges shuffled and
  * turned either way. */
std::vector<Edge>
cycle (std::uint32_t n, std::uint32_t first, std::uint32_t step, std::mt19937& random)
{
  std::vector<Edge> edges;
  for (std::uint32_t i = 0; i < n; ++i)
  {
    Edge e{first + step * i, first + step * ((i + 1) % n)};
    if (random () % 2)
      std::swap (e[0], e[1]);
    edges.push_back (e);
  }
  std::shuffle (edges.begin (), edges.end (), random);
  return edges;
}

TEST (LinkCycle, OneCycleOfAnyLengthAndOrder)
{
  std::mt19937 random (1);
  for (std::uint32_t n : {3u, 4u, 5u, 17u, 31u, 32u, 33u, 200u})
  {
    SCOPED_TRACE (n);
    EXPECT_TRUE (byTheEngine (cycle (n, 1000, 7, random)));
  }
}

TEST (LinkCycle, NotOneCycle)
{
  std::mt19937 random (2);
  EXPECT_FALSE (byTheEngine ({}));
  EXPECT_FALSE (byTheEngine ({{1, 2}}));
  EXPECT_FALSE (byTheEngine ({{1, 2}, {2, 3}})); // a path
  EXPECT_FALSE (byTheEngine ({{1, 2}, {2, 3}, {3, 4}})); // a longer path
  auto two = cycle (5, 0, 1, random);            // two fans: a pinched vertex
  const auto other = cycle (4, 10, 1, random);
  two.insert (two.end (), other.begin (), other.end ());
  EXPECT_FALSE (byTheEngine (two));
  // Two cycles through one vertex: a figure eight (a pinched edge seen from its end).
  EXPECT_FALSE (byTheEngine ({{0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 4}, {4, 0}}));
  // A cycle with a chord.
  EXPECT_FALSE (byTheEngine ({{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}}));
  // Long enough to leave the stack: two cycles of 40.
  auto long_two = cycle (40, 0, 1, random);
  const auto long_other = cycle (40, 100, 1, random);
  long_two.insert (long_two.end (), long_other.begin (), long_other.end ());
  EXPECT_FALSE (byTheEngine (long_two));
}

TEST (LinkCycle, AgreesWithAGraphSearchOnRandomEdgeSets)
{
  std::mt19937 random (3);
  const auto below = [&] (std::uint32_t k) { return static_cast<std::uint32_t> (random () % k); };
  std::size_t cycles = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    // Distinct edges on a few vertices, often a cycle with an edge more, less or changed.
    const std::uint32_t n = 3 + below (8);
    std::vector<Edge> edges = cycle (n, 0, 1, random);
    switch (below (4))
    {
    case 0:
      break;
    case 1:
      edges.pop_back ();
      break;
    case 2:
      edges.push_back ({n, below (n)});
      edges.push_back ({n, below (n)});
      break;
    default: edges.back ()[below (2)] = n + below (3);
    }
    std::set<std::pair<std::uint32_t, std::uint32_t>> distinct;
    bool simple = true;
    for (const auto& e : edges)
      simple = simple && e[0] != e[1] && distinct.emplace (std::min (e[0], e[1]), std::max (e[0], e[1])).second;
    if (!simple)
      continue;
    const bool expected = byGraphSearch (edges);
    ASSERT_EQ (byTheEngine (edges), expected) << "trial " << trial;
    cycles += expected;
  }
  EXPECT_GT (cycles, 3000u);
}

} // namespace
} // namespace pcl_wrap::test
