// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// Topological facts about complexes and triangle meshes, computed independently of the engine.
#include <array>
#include <cstdint>
#include <map>
#include <vector>

namespace pcl_wrap::test
{

using Tuple = std::vector<std::uint32_t>;
using Triangle = std::array<std::uint32_t, 3>;

struct Homology
{
  std::size_t components = 0; // beta_0
  long euler = 0;             // sum of (-1)^k #k-simplices
  std::size_t betti1 = 0;     // over GF(2)
};

/** Connectivity, Euler characteristic and first Betti number of a simplicial complex given as
  * sorted vertex tuples (closed under faces). */
Homology
homology (const std::vector<Tuple>& complex);

/** Is every face of every simplex in the list? */
bool
closedUnderFaces (const std::vector<Tuple>& complex);

/** How many triangles use each undirected edge (a < b). */
std::map<std::pair<std::uint32_t, std::uint32_t>, int>
edgeUses (const std::vector<Triangle>& triangles);

struct SurfaceReport
{
  bool closed_manifold = false;  // every edge in exactly 2 triangles, every vertex link one cycle
  bool consistently_oriented = false; // every directed edge used at most once
  std::size_t vertices = 0, edges = 0, components = 0;
  long euler = 0;
};

/** Do the edges make one cycle: connected, every vertex on exactly two of them? */
bool
isOneCycle (const std::vector<std::pair<std::uint32_t, std::uint32_t>>& edges);

SurfaceReport
describeSurface (const std::vector<Triangle>& triangles);

/** An oriented 2-manifold with boundary, as a user checks one. */
struct OpenSurfaceReport
{
  bool manifold = false;               // every edge in 1 or 2 triangles, every vertex link one path or cycle
  bool consistently_oriented = false;  // every directed edge used at most once
  bool no_duplicate_triangles = false; // no two triangles on the same three vertices
  std::size_t vertices = 0, boundary_edges = 0, components = 0;
  std::size_t largest_component_vertices = 0;
  long euler = 0, largest_component_euler = 0;
};

OpenSurfaceReport
describeOpenSurface (const std::vector<Triangle>& triangles);

} // namespace pcl_wrap::test
