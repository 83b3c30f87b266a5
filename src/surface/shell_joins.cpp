// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/shell_joins.h"

#include "surface/shell_pieces.h"
#include "util/union_find.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t NONE = ~std::uint32_t (0);

} // namespace

std::size_t
joinAlongSharedEdges (ManifoldSplit& split, std::uint32_t nv)
{
  auto& triangles = split.triangles;
  const auto base = [&] (std::uint32_t v) { return split.original (v, nv); };
  UnionFind piece = piecesOf (split, nv);
  // Every triangle side, by the undirected edge of the points it joins.
  std::vector<std::pair<std::uint64_t, std::uint32_t>> by_edge;
  by_edge.reserve (3 * triangles.size ());
  for (std::uint32_t i = 0; i < triangles.size (); ++i)
    for (int k = 0; k < 3; ++k)
      by_edge.emplace_back (edgeKey (base (triangles[i][k]), base (triangles[i][(k + 1) % 3])), i);
  std::sort (by_edge.begin (), by_edge.end ());

  UnionFind merged (piece.size ()), same (piece.size ()); // pieces joined; ids made one
  std::vector<std::uint8_t> gone (triangles.size (), 0), busy (piece.size (), 0);
  std::vector<std::array<std::uint32_t, 3>> added;
  std::size_t joins = 0;
  for (std::size_t e = 0; e < by_edge.size ();)
  {
    std::size_t f = e;
    while (f < by_edge.size () && by_edge[f].first == by_edge[e].first)
      ++f;
    const std::size_t first = std::exchange (e, f);
    if (f - first < 4 || (f - first) % 2 != 0)
      continue; // an edge of one piece, or of an odd number of triangles
    const std::uint32_t a = std::uint32_t (by_edge[first].first >> 32), b = std::uint32_t (by_edge[first].first);
    std::vector<std::uint32_t> on;
    for (std::size_t k = first; k < f; ++k)
      on.push_back (by_edge[k].second);
    if (std::any_of (on.begin (), on.end (), [&] (std::uint32_t i) { return gone[i]; }))
      continue;
    std::sort (on.begin (), on.end (), [&] (std::uint32_t i, std::uint32_t j) {
      return std::make_pair (piece.find (triangles[i][0]), i) < std::make_pair (piece.find (triangles[j][0]), j);
    });
    // Per piece: its triangle from a to b and its triangle back, as (a's id, b's id, third vertex).
    const std::size_t k = on.size () / 2;
    std::vector<std::uint32_t> owner (k);
    std::vector<std::array<std::uint32_t, 3>> forth (k), back (k);
    bool fits = true;
    for (std::size_t i = 0; i < k && fits; ++i)
    {
      owner[i] = piece.find (triangles[on[2 * i]][0]);
      fits = piece.find (triangles[on[2 * i + 1]][0]) == owner[i] && (i == 0 || owner[i] != owner[i - 1]);
      int ways = 0;
      for (std::size_t j = 2 * i; j < 2 * i + 2; ++j)
      {
        std::array<std::uint32_t, 3> t = triangles[on[j]];
        while (base (t[0]) != a)
          std::rotate (t.begin (), t.begin () + 1, t.end ());
        if (base (t[1]) == b)
        {
          forth[i] = t;
          ways |= 1;
        }
        else
        {
          back[i] = {t[0], t[2], t[1]};
          ways |= 2;
        }
      }
      // One triangle each way, through the same copies of a and b, none touched by a join yet.
      fits = fits && ways == 3 && forth[i][0] == back[i][0] && forth[i][1] == back[i][1];
      for (const auto* t : {&forth[i], &back[i]})
        for (std::uint32_t v : *t)
          fits = fits && !busy[v];
    }
    for (std::size_t i = 0; i < k && fits; ++i)
      for (std::size_t j = 0; j < i && fits; ++j)
        fits = merged.find (owner[i]) != merged.find (owner[j]);
    if (!fits)
      continue;
    // The new diagonals (u, w), piece i's third vertex and the next piece's, must differ.
    std::vector<std::uint64_t> diagonals (k);
    for (std::size_t i = 0; i < k; ++i)
      diagonals[i] = edgeKey (forth[i][2], back[(i + 1) % k][2]);
    std::sort (diagonals.begin (), diagonals.end ());
    if (std::adjacent_find (diagonals.begin (), diagonals.end ()) != diagonals.end ())
      continue;
    const std::uint32_t ia = forth[0][0], ib = forth[0][1];
    for (std::size_t i = 0; i < k; ++i)
    {
      const std::uint32_t u = forth[i][2], w = back[(i + 1) % k][2];
      added.push_back ({ia, w, u});
      added.push_back ({w, ib, u});
      same.attach (forth[i][0], ia); // both roots: no join has touched them
      same.attach (forth[i][1], ib);
      merged.attach (owner[i], owner[0]);
      for (const auto* t : {&forth[i], &back[i]})
        for (std::uint32_t v : *t)
          busy[v] = 1;
    }
    for (std::uint32_t i : on)
      gone[i] = 1;
    joins += k - 1;
  }
  if (joins == 0)
    return 0;
  std::size_t n = 0;
  for (std::uint32_t i = 0; i < triangles.size (); ++i)
    if (!gone[i])
      triangles[n++] = triangles[i];
  triangles.resize (n);
  triangles.insert (triangles.end (), added.begin (), added.end ());
  for (auto& t : triangles)
    for (std::uint32_t& v : t)
      v = same.find (v);
  return joins;
}

void
dropUnusedCopies (ManifoldSplit& split, std::uint32_t nv)
{
  std::vector<std::uint32_t> renamed (split.copy_of.size (), NONE);
  for (const auto& t : split.triangles)
    for (std::uint32_t v : t)
      if (v >= nv)
        renamed[v - nv] = 0;
  std::uint32_t kept = 0;
  for (std::uint32_t c = 0; c < renamed.size (); ++c)
    if (renamed[c] != NONE)
    {
      split.copy_of[kept] = split.copy_of[c];
      renamed[c] = nv + kept++;
    }
  split.copy_of.resize (kept);
  for (auto& t : split.triangles)
    for (std::uint32_t& v : t)
      if (v >= nv)
        v = renamed[v - nv];
}

} // namespace pcl_wrap::detail
