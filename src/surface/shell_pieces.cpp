// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/shell_pieces.h"

#include <algorithm>

namespace pcl_wrap::detail
{

UnionFind
piecesOf (const ManifoldSplit& split, std::uint32_t nv)
{
  UnionFind piece (nv + split.copy_of.size ());
  for (const auto& t : split.triangles)
  {
    piece.attach (t[1], t[0]);
    piece.attach (t[2], t[0]);
  }
  return piece;
}

ShellTopology
topologyOf (const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  std::vector<std::uint32_t> vertices;
  for (const auto& t : triangles)
    vertices.insert (vertices.end (), t.begin (), t.end ());
  std::sort (vertices.begin (), vertices.end ());
  vertices.erase (std::unique (vertices.begin (), vertices.end ()), vertices.end ());
  const auto index = [&] (std::uint32_t v) {
    return static_cast<std::uint32_t> (std::lower_bound (vertices.begin (), vertices.end (), v) - vertices.begin ());
  };
  UnionFind piece (vertices.size ());
  for (const auto& t : triangles)
  {
    piece.attach (index (t[1]), index (t[0]));
    piece.attach (index (t[2]), index (t[0]));
  }
  ShellTopology out;
  for (std::uint32_t v = 0; v < piece.size (); ++v)
    out.pieces += piece.isRoot (v);
  // Closed: every edge in two triangles, E = 3F / 2.
  out.euler = long (vertices.size ()) - long (3 * triangles.size () / 2) + long (triangles.size ());
  return out;
}

} // namespace pcl_wrap::detail
