// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/union_find.h"
#include "wrap/manifold_split.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The vertices of \a split (over \a nv vertices, copies included) by piece: vertices
  * connected through triangles have one root. */
UnionFind
piecesOf (const ManifoldSplit& split, std::uint32_t nv);

/** \brief The pieces of a closed surface and its Euler characteristic. */
struct ShellTopology
{
  std::size_t pieces = 0;
  long euler = 0;
  long genus () const { return (2 * long (pieces) - euler) / 2; }
};

/** \brief The topology of \a triangles, a closed surface (every edge in two triangles). */
ShellTopology
topologyOf (const std::vector<std::array<std::uint32_t, 3>>& triangles);

} // namespace pcl_wrap::detail
