// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Where the surface stage looks for small handles to cut (docs/surface.md §2): on tori made of
// quads, a handle a few rings around is found, a large or long one is not.
#include "surface/surface_handles.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

using Triangle = std::array<std::uint32_t, 3>;

/** A torus of \a around x \a tube vertices, each quad cut into two triangles, consistently
  * oriented; vertex ids from \a first on. */
void
addTorus (std::uint32_t around, std::uint32_t tube, std::uint32_t first, std::vector<Triangle>& triangles)
{
  const auto id = [&] (std::uint32_t i, std::uint32_t j) { return first + (i % around) * tube + j % tube; };
  for (std::uint32_t i = 0; i < around; ++i)
    for (std::uint32_t j = 0; j < tube; ++j)
    {
      triangles.push_back ({id (i, j), id (i + 1, j), id (i + 1, j + 1)});
      triangles.push_back ({id (i, j), id (i + 1, j + 1), id (i, j + 1)});
    }
}

/** An octahedron: a sphere, genus 0. */
void
addOctahedron (std::uint32_t first, std::vector<Triangle>& triangles)
{
  const std::uint32_t top = first, bottom = first + 5;
  for (std::uint32_t k = 0; k < 4; ++k)
  {
    const std::uint32_t a = first + 1 + k, b = first + 1 + (k + 1) % 4;
    triangles.push_back ({top, a, b});
    triangles.push_back ({bottom, b, a});
  }
}

TEST (SurfaceHandles, SmallTorusIsOneHandleEverywhere)
{
  std::vector<Triangle> triangles;
  addTorus (8, 6, 0, triangles);
  const std::vector<std::uint32_t> found = detail::verticesOnSmallHandles (triangles, 48);
  EXPECT_FALSE (found.empty ());
  EXPECT_LT (found.back (), 48u);
}

TEST (SurfaceHandles, LargeOrLongHandlesAreNotSmall)
{
  // A thick torus: every patch is a disc. A thin ring: the patches go round its tube, but the
  // ring closes far away, as a finger's or a tail's tube does not close at all.
  for (const auto& [around, tube] : {std::pair{60u, 30u}, {80u, 5u}})
  {
    std::vector<Triangle> triangles;
    addTorus (around, tube, 0, triangles);
    EXPECT_TRUE (detail::verticesOnSmallHandles (triangles, around * tube).empty ()) << around << " x " << tube;
  }
}

TEST (SurfaceHandles, OnlyThePartWithTheSmallHandle)
{
  // A sphere, a thick torus and a small torus, with unused vertex ids between them.
  std::vector<Triangle> triangles;
  addOctahedron (0, triangles);
  addTorus (60, 30, 10, triangles);
  addTorus (8, 6, 2000, triangles);
  const std::vector<std::uint32_t> found = detail::verticesOnSmallHandles (triangles, 2100);
  ASSERT_FALSE (found.empty ());
  EXPECT_GE (found.front (), 2000u);
  EXPECT_LT (found.back (), 2048u);
  triangles.clear ();
  addOctahedron (0, triangles);
  EXPECT_TRUE (detail::verticesOnSmallHandles (triangles, 6).empty ());
}

} // namespace
} // namespace pcl_wrap::test
