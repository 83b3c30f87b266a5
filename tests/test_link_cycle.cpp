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

detail::LinkShape
shapeOf (const std::vector<Edge>& edges)
{
  return detail::linkShape (edges.size (), [&] (std::size_t e) { return std::make_pair (edges[e][0], edges[e][1]); });
}

TEST (LinkCycle, TheShortWalkAgreesWithTheSortedEnds)
{
  // isOneCycle() walks a short link before it sorts its ends: on any edges, repeated, turned and
  // looped ones too, both must say the same.
  std::mt19937 random (5);
  const auto below = [&] (std::uint32_t k) { return static_cast<std::uint32_t> (random () % k); };
  std::size_t cycles = 0;
  for (int trial = 0; trial < 50000; ++trial)
  {
    const std::uint32_t n = 3 + below (16);
    std::vector<Edge> edges = cycle (n, 0, 1, random);
    for (std::uint32_t change = below (3); change-- > 0;)
      switch (below (5))
      {
      case 0: edges.pop_back (); break;
      case 1: edges.push_back (edges[below (static_cast<std::uint32_t> (edges.size ()))]); break;
      case 2: edges.push_back ({below (n + 2), below (n + 2)}); break;
      case 3: edges[below (static_cast<std::uint32_t> (edges.size ()))][below (2)] = below (n + 2); break;
      default: std::swap (edges.front (), edges[below (static_cast<std::uint32_t> (edges.size ()))]);
      }
    const detail::LinkShape shape = shapeOf (edges);
    const bool expected = edges.size () >= 3 && shape.cycles && shape.parts == 1;
    ASSERT_EQ (byTheEngine (edges), expected) << "trial " << trial;
    cycles += expected;
  }
  EXPECT_GT (cycles, 15000u);
}

/** The connected parts of the graph of \a edges, by a depth-first search; \a part, if given, gets
  * each edge's part, numbered from 0. */
std::uint32_t
partsBySearch (const std::vector<Edge>& edges, std::vector<std::uint32_t>* part = nullptr)
{
  std::vector<std::uint8_t> seen (edges.size (), 0);
  if (part)
    part->assign (edges.size (), 0);
  std::uint32_t parts = 0;
  for (std::size_t start = 0; start < edges.size (); ++start)
  {
    if (seen[start])
      continue;
    ++parts;
    std::vector<std::size_t> stack{start};
    seen[start] = 1;
    while (!stack.empty ())
    {
      if (part)
        (*part)[stack.back ()] = parts - 1;
      const Edge e = edges[stack.back ()];
      stack.pop_back ();
      for (std::size_t f = 0; f < edges.size (); ++f)
        if (!seen[f] && (edges[f][0] == e[0] || edges[f][0] == e[1] || edges[f][1] == e[0] || edges[f][1] == e[1]))
        {
          seen[f] = 1;
          stack.push_back (f);
        }
    }
  }
  return parts;
}

TEST (LinkCycle, PartsAreTheGraphsConnectedParts)
{
  // A few cycles and paths on shared and separate vertices, short and long (past the stack).
  std::mt19937 random (4);
  const auto below = [&] (std::uint32_t k) { return static_cast<std::uint32_t> (random () % k); };
  std::size_t several = 0;
  for (int trial = 0; trial < 3000; ++trial)
  {
    std::vector<Edge> edges;
    const std::uint32_t pieces = 1 + below (4);
    for (std::uint32_t p = 0; p < pieces; ++p)
    {
      auto piece = cycle (3 + below (trial % 10 == 0 ? 40 : 6), below (2) ? 0 : 100 * (p + 1), 1, random);
      if (below (3) == 0)
        piece.pop_back (); // a path
      edges.insert (edges.end (), piece.begin (), piece.end ());
    }
    std::shuffle (edges.begin (), edges.end (), random);
    const detail::LinkShape shape = shapeOf (edges);
    std::vector<std::uint32_t> part;
    const std::uint32_t expected = partsBySearch (edges, &part);
    ASSERT_EQ (shape.parts, expected) << "trial " << trial;
    several += expected > 1;
    // Each edge named by an edge of its own part, the same for the whole part.
    std::vector<std::uint32_t> part_of (edges.size ());
    detail::linkShape (
        edges.size (), [&] (std::size_t e) { return std::make_pair (edges[e][0], edges[e][1]); }, part_of.data ());
    for (std::size_t a = 0; a < edges.size (); ++a)
    {
      ASSERT_EQ (part[part_of[a]], part[a]) << "trial " << trial;
      for (std::size_t b = 0; b < a; ++b)
        ASSERT_EQ (part_of[a] == part_of[b], part[a] == part[b]) << "trial " << trial;
    }
  }
  EXPECT_GT (several, 500u);
  // Two fans at a pinch are two cycles; a third triangle on an edge makes two cycles share an end.
  std::vector<Edge> two = cycle (5, 0, 1, random), other = cycle (4, 10, 1, random);
  two.insert (two.end (), other.begin (), other.end ());
  EXPECT_EQ (shapeOf (two).parts, 2u);
  EXPECT_TRUE (shapeOf (two).cycles);
  const std::vector<Edge> eight{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {3, 4}, {4, 0}};
  EXPECT_EQ (shapeOf (eight).parts, 1u);
  EXPECT_FALSE (shapeOf (eight).cycles);
}

} // namespace
} // namespace pcl_wrap::test
