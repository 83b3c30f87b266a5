// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// Where the surface stage looks for small handles to cut (docs/surface.md §2): on tori made of
// quads, a handle a few rings around is found, a large or long one is not; on the boundary of a
// plate of voxels, a tunnel one voxel wide is found as a tunnel, a wide hole is not; a surface
// touching itself at a vertex has no handle there, nor does a sphere touching a torus at a vertex
// hide the torus's; asked to look near some vertices only, it
// looks nowhere else; on a surface of genus 0, a thin bar between two slabs is found from the
// sharp saddles at its ends.
#include "surface/surface_handles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <array>
#include <cstdint>
#include <random>
#include <set>
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

/** The boundary of a solid of unit voxels within \a size x \a size x \a height, those where
  * \a solid (x, y, z) holds: each boundary square of a voxel cut into two triangles, oriented
  * outwards. Vertex ids number the grid's corners, x fastest (voxelCorner()). */
template <class Solid>
std::vector<Triangle>
voxelBoundary (int size, int height, const Solid& solid)
{
  const auto inside = [&] (int x, int y, int z) {
    return x >= 0 && y >= 0 && z >= 0 && x < size && y < size && z < height && solid (x, y, z);
  };
  const auto id = [&] (std::array<int, 3> c) {
    return static_cast<std::uint32_t> (c[0] + (size + 1) * (c[1] + (size + 1) * c[2]));
  };
  std::vector<Triangle> triangles;
  for (int x = 0; x < size; ++x)
    for (int y = 0; y < size; ++y)
      for (int z = 0; z < height; ++z)
        for (int a = 0; a < 3; ++a)
          for (int sign : {-1, 1})
          {
            std::array<int, 3> next{x, y, z};
            next[a] += sign;
            if (!inside (x, y, z) || inside (next[0], next[1], next[2]))
              continue;
            // The square on the voxel's face across axis a, counter-clockwise seen from outside.
            const int b = (a + 1) % 3, c = (a + 2) % 3;
            std::array<std::array<int, 3>, 4> corner;
            const int steps[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            for (int k = 0; k < 4; ++k)
            {
              const int i = sign > 0 ? k : 3 - k;
              corner[k] = {x, y, z};
              corner[k][a] += sign > 0;
              corner[k][b] += steps[i][0];
              corner[k][c] += steps[i][1];
            }
            triangles.push_back ({id (corner[0]), id (corner[1]), id (corner[2])});
            triangles.push_back ({id (corner[0]), id (corner[2]), id (corner[3])});
          }
  return triangles;
}

/** The grid corner of vertex \a id of voxelBoundary (size, ...). */
std::array<int, 3>
voxelCorner (std::uint32_t id, int size)
{
  const auto n = static_cast<std::uint32_t> (size + 1);
  return {static_cast<int> (id % n), static_cast<int> (id / n % n), static_cast<int> (id / (n * n))};
}

/** The boundary of a plate of \a size x \a size x \a thickness unit voxels with a hole of \a hole
  * x \a length voxels (square by default) through its middle. */
std::vector<Triangle>
plateWithHole (int size, int thickness, int hole, int length = 0)
{
  length = length > 0 ? length : hole;
  const int lo = (size - hole) / 2, low = (size - length) / 2;
  return voxelBoundary (size, thickness, [&] (int x, int y, int) {
    return !(x >= lo && x < lo + hole && y >= low && y < low + length);
  });
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
  const std::vector<std::uint32_t> found = detail::smallHandlePatches (triangles, 48).centres;
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
    const detail::SmallHandlePatches patches = detail::smallHandlePatches (triangles, around * tube);
    EXPECT_TRUE (patches.centres.empty ()) << around << " x " << tube;
    EXPECT_TRUE (patches.has_genus) << "a torus, whose handle is not small";
  }
}

/** A thin ring of \a rows rows of vertices around its tube, 4 to 8 in each (drawn by \a rng), at
  * random angles; consecutive rows joined by a strip of triangles, each taking the next vertex
  * of the row whose next angle is smaller, consistently oriented: a tube whose triangles are as
  * irregular as a sampled surface's. */
std::vector<Triangle>
irregularRing (std::uint32_t rows, std::mt19937& rng)
{
  std::uniform_int_distribution<std::uint32_t> count (4, 8);
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  std::vector<std::vector<double>> angle (rows);
  std::vector<std::uint32_t> first (rows + 1, 0);
  for (std::uint32_t i = 0; i < rows; ++i)
  {
    const std::uint32_t n = count (rng);
    for (std::uint32_t k = 0; k < n; ++k)
      angle[i].push_back ((k + 0.8 * unit (rng)) / n);
    first[i + 1] = first[i] + n;
  }
  std::vector<Triangle> triangles;
  for (std::uint32_t i = 0; i < rows; ++i)
  {
    const std::uint32_t j = (i + 1) % rows;
    const auto m = static_cast<std::uint32_t> (angle[i].size ()), n = static_cast<std::uint32_t> (angle[j].size ());
    // Walk both rows once around, from their first vertices.
    std::uint32_t a = 0, b = 0;
    while (a < m || b < n)
    {
      const double next_a = a < m ? (a + 1 < m ? angle[i][a + 1] : 1.0 + angle[i][0]) : 2.0,
                   next_b = b < n ? (b + 1 < n ? angle[j][b + 1] : 1.0 + angle[j][0]) : 2.0;
      const std::uint32_t pa = first[i] + a % m, pb = first[j] + b % n;
      if (next_a <= next_b)
      {
        triangles.push_back ({pa, pb, first[i] + (a + 1) % m});
        ++a;
      }
      else
      {
        triangles.push_back ({pa, pb, first[j] + (b + 1) % n});
        ++b;
      }
    }
  }
  return triangles;
}

TEST (SurfaceHandles, ABandRoundAThinTubeWhoseRimsMeetIsNoHandle)
{
  // Thin rings with irregular triangles: a patch round the tube can be a band whose two rims
  // meet at a vertex, where its triangles make two fans. Counted once, that vertex would give
  // the band (V - E + F = -1, one loop) a genus of its own, and the ring's tube would be cut as a
  // small handle's; counted once per fan, the band is an annulus, and the ring closes far away.
  std::mt19937 rng (7);
  for (int k = 0; k < 100; ++k)
  {
    const std::vector<Triangle> ring = irregularRing (60, rng);
    std::uint32_t n = 0;
    for (const Triangle& t : ring)
      n = std::max ({n, t[0] + 1, t[1] + 1, t[2] + 1});
    // A closed oriented surface: each edge once either way.
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
    for (const Triangle& t : ring)
      for (int i = 0; i < 3; ++i)
        ASSERT_TRUE (directed.insert ({t[i], t[(i + 1) % 3]}).second);
    for (const auto& [a, b] : directed)
      ASSERT_TRUE (directed.count ({b, a}));
    const detail::SmallHandlePatches patches = detail::smallHandlePatches (ring, n);
    EXPECT_TRUE (patches.centres.empty ()) << "ring " << k;
    EXPECT_TRUE (patches.has_genus);
  }
}

TEST (SurfaceHandles, OnlyThePartWithTheSmallHandle)
{
  // A sphere, a thick torus and a small torus, with unused vertex ids between them.
  std::vector<Triangle> triangles;
  addOctahedron (0, triangles);
  addTorus (60, 30, 10, triangles);
  addTorus (8, 6, 2000, triangles);
  const std::vector<std::uint32_t> found = detail::smallHandlePatches (triangles, 2100).centres;
  ASSERT_FALSE (found.empty ());
  EXPECT_GE (found.front (), 2000u);
  EXPECT_LT (found.back (), 2048u);
  triangles.clear ();
  addOctahedron (0, triangles);
  EXPECT_TRUE (detail::smallHandlePatches (triangles, 6).centres.empty ());
}

/** A tube of \a around x \a along vertices with ids from \a first on, capped at both ends by one
  * vertex, \a apex: a sphere whose two poles touch, genus 0 once split there. */
std::vector<Triangle>
sphereTouchingItself (std::uint32_t around, std::uint32_t along, std::uint32_t apex, std::uint32_t first = 0)
{
  std::vector<Triangle> triangles;
  const auto id = [&] (std::uint32_t i, std::uint32_t j) { return first + (i % around) * along + j; };
  for (std::uint32_t i = 0; i < around; ++i)
  {
    for (std::uint32_t j = 0; j + 1 < along; ++j)
    {
      triangles.push_back ({id (i, j), id (i + 1, j), id (i + 1, j + 1)});
      triangles.push_back ({id (i, j), id (i + 1, j + 1), id (i, j + 1)});
    }
    triangles.push_back ({apex, id (i + 1, 0), id (i, 0)});
    triangles.push_back ({apex, id (i, along - 1), id (i + 1, along - 1)});
  }
  return triangles;
}

TEST (SurfaceHandles, APinchIsNoHandle)
{
  // V - F / 2 is 1, as for a torus, but the apex is two fans: no handle to look for. (Taken for a
  // torus, the surface has patches round its tube whose ends join near the apex.) The same tube
  // closed into a torus is a small handle.
  const detail::SmallHandlePatches pinched = detail::smallHandlePatches (sphereTouchingItself (6, 8, 48), 49);
  EXPECT_TRUE (pinched.centres.empty ());
  EXPECT_FALSE (pinched.has_genus);
  std::vector<Triangle> torus;
  addTorus (8, 6, 0, torus);
  EXPECT_FALSE (detail::smallHandlePatches (torus, 48).centres.empty ());
  // However many triangles meet there: three such spheres touching at one apex, 36 triangles in
  // six fans.
  std::vector<Triangle> three;
  for (std::uint32_t k = 0; k < 3; ++k)
  {
    const std::vector<Triangle> sphere = sphereTouchingItself (6, 8, 144, 48 * k);
    three.insert (three.end (), sphere.begin (), sphere.end ());
  }
  EXPECT_TRUE (detail::smallHandlePatches (three, 145).centres.empty ());
}

TEST (SurfaceHandles, ASphereTouchingATorusAtAVertexHidesNoHandle)
{
  // A small torus (ids 0..47) and an octahedron whose first vertex is the torus's vertex 0: one
  // piece through that vertex, whose V - F / 2 (the vertex counted once per fan) is 0 + 2, a
  // sphere's. Apart at the vertex, they are a torus and a sphere: the torus's handle is found.
  std::vector<Triangle> triangles;
  addTorus (8, 6, 0, triangles);
  std::vector<Triangle> octahedron;
  addOctahedron (48, octahedron);
  for (Triangle& t : octahedron)
  {
    std::replace (t.begin (), t.end (), 48u, 0u);
    triangles.push_back (t);
  }
  const detail::SmallHandlePatches patches = detail::smallHandlePatches (triangles, 54);
  EXPECT_TRUE (patches.has_genus);
  ASSERT_FALSE (patches.centres.empty ());
  EXPECT_LT (patches.centres.back (), 48u) << "on the torus only";
  // Two such spheres, at two vertices: the same.
  for (Triangle t : octahedron)
  {
    for (std::uint32_t& v : t)
      v = v == 0 ? 20 : v + 6;
    triangles.push_back (t);
  }
  EXPECT_TRUE (detail::smallHandlePatches (triangles, 60).has_genus);
}

TEST (SurfaceHandles, OnlyNearTheGivenVertices)
{
  // Two small tori, ids 0..47 and 100..147: near a vertex of the second, only its centres; near
  // vertices of neither (unused ids), none.
  std::vector<Triangle> triangles;
  addTorus (8, 6, 0, triangles);
  addTorus (8, 6, 100, triangles);
  const std::vector<std::uint32_t> second{120}, neither{60, 70};
  const std::vector<std::uint32_t> found = detail::smallHandlePatches (triangles, 148, &second).centres;
  ASSERT_FALSE (found.empty ());
  EXPECT_GE (found.front (), 100u);
  EXPECT_FALSE (detail::smallHandlePatches (triangles, 148).centres.front () >= 100u); // both, unrestricted
  EXPECT_TRUE (detail::smallHandlePatches (triangles, 148, &neither).centres.empty ());
}

TEST (SurfaceHandles, TunnelThroughAWallIsFound)
{
  // A tunnel one voxel wide through a plate three thick: its ends join only round the plate's
  // edge, far away, but the surface opens out past both. A hole six voxels wide is a real one.
  const int size = 30, thickness = 3;
  const auto num_vertices = static_cast<std::uint32_t> ((size + 1) * (size + 1) * (thickness + 1));
  const detail::SmallHandlePatches plate =
      detail::smallHandlePatches (plateWithHole (size, thickness, 1), num_vertices);
  ASSERT_FALSE (plate.centres.empty ());
  for (std::size_t i = 0; i < plate.centres.size (); ++i)
  {
    EXPECT_TRUE (plate.tunnel[i]);
    // Near the tunnel, whose corners have x and y 14 or 15.
    const std::uint32_t x = plate.centres[i] % (size + 1), y = plate.centres[i] / (size + 1) % (size + 1);
    EXPECT_LE (std::max (x > 15 ? x - 15 : 14 - std::min (x, 14u), y > 15 ? y - 15 : 14 - std::min (y, 14u)), 2u)
        << x << " " << y;
    // Each patch holds its centre.
    EXPECT_TRUE (std::binary_search (plate.vertices.begin () + plate.begin[i],
                                     plate.vertices.begin () + plate.begin[i + 1], plate.centres[i]));
  }
  EXPECT_TRUE (detail::smallHandlePatches (plateWithHole (size, thickness, 6), num_vertices).centres.empty ());
}

/** The corners of voxelBoundary (size, ...) where they are, but for those half way through a plate
  * two thick on the walls x = \a x0 and x = \a x1 of a hole, moved \a bulge away from its middle:
  * the hole's corners on the plate's faces are then sharp saddles, as where a hole through a
  * sampled wall meets its faces. */
std::vector<std::array<double, 3>>
bulgingHolePositions (int size, int x0, int x1, double bulge)
{
  std::vector<std::array<double, 3>> positions (static_cast<std::size_t> ((size + 1) * (size + 1) * 3));
  for (std::uint32_t v = 0; v < positions.size (); ++v)
  {
    const std::array<int, 3> c = voxelCorner (v, size);
    positions[v] = {double (c[0]), double (c[1]), double (c[2])};
    if (c[2] == 1 && (c[0] == x0 || c[0] == x1))
      positions[v][0] += c[0] == x0 ? -bulge : bulge;
  }
  return positions;
}

TEST (SurfaceHandles, ASlitThroughAWallIsFoundInWiderPatches)
{
  // A slit one voxel wide and five long through a plate two thick: a patch of HANDLE_RINGS rings
  // does not go round it, one of WIDE_TUNNEL_RINGS around a sharp saddle at its corners does.
  // Holes ten voxels wide are real ones.
  const int size = 40;
  const auto num_vertices = static_cast<std::uint32_t> ((size + 1) * (size + 1) * 3);
  const std::vector<Triangle> slit = plateWithHole (size, 2, 1, 5);
  const std::vector<std::array<double, 3>> positions = bulgingHolePositions (size, 19, 20, 0.3);
  EXPECT_TRUE (detail::smallHandlePatches (slit, num_vertices, nullptr, &positions).centres.empty ());
  const detail::SmallHandlePatches wide = detail::wideTunnelPatches (slit, num_vertices, positions);
  ASSERT_FALSE (wide.centres.empty ());
  for (std::size_t i = 0; i < wide.centres.size (); ++i)
  {
    EXPECT_TRUE (wide.tunnel[i]);
    // On the slit's wall, whose corners have x 19 or 20 and y 17 to 22.
    const std::array<int, 3> c = voxelCorner (wide.centres[i], size);
    EXPECT_TRUE ((c[0] == 19 || c[0] == 20) && c[1] >= 17 && c[1] <= 22) << c[0] << " " << c[1] << " " << c[2];
  }
  // On a plate as rough as it is thick, sharp saddles are common and mark no tube: nothing is
  // looked at.
  std::vector<std::array<double, 3>> noisy = positions;
  for (std::uint32_t v = 0; v < num_vertices; ++v)
    noisy[v][2] += 2.0 * ((v * 2654435761u) % 1024 / 1024.0 - 0.5);
  EXPECT_TRUE (detail::wideTunnelPatches (slit, num_vertices, noisy).centres.empty ());
  for (const auto& [hole, length] : {std::pair{10, 10}, {6, 16}})
  {
    const int x0 = (size - hole) / 2;
    EXPECT_TRUE (detail::wideTunnelPatches (plateWithHole (size, 2, hole, length), num_vertices,
                                            bulgingHolePositions (size, x0, x0 + hole, 0.3))
                     .centres.empty ())
        << hole << " x " << length;
  }
}

TEST (SurfaceHandles, TunnelLevelsRunFromOneFaceToTheOther)
{
  // Along the tunnel through the plate, a patch's vertices on the plate's top face are nearer one
  // of its ends than the other, those on the bottom face the other way round: the levels of one
  // face are at most zero and those of the other at least zero (a vertex at a mouth of a tunnel
  // as long as the patch is wide may be as near both), and neither face is all zero.
  const int size = 30, thickness = 3;
  const auto num_vertices = static_cast<std::uint32_t> ((size + 1) * (size + 1) * (thickness + 1));
  const detail::SmallHandlePatches plate =
      detail::smallHandlePatches (plateWithHole (size, thickness, 1), num_vertices);
  ASSERT_EQ (plate.level.size (), plate.vertices.size ());
  int across = 0; // patches that reach both faces
  for (std::size_t i = 0; i < plate.centres.size (); ++i)
  {
    ASSERT_TRUE (plate.tunnel[i]);
    std::array<int, 2> lowest{INT8_MAX, INT8_MAX}, highest{INT8_MIN, INT8_MIN}; // bottom face, top face
    for (std::uint32_t k = plate.begin[i]; k < plate.begin[i + 1]; ++k)
    {
      const std::uint32_t z = plate.vertices[k] / ((size + 1) * (size + 1));
      if (z != 0 && z != thickness)
        continue;
      const int face = z == thickness;
      lowest[face] = std::min<int> (lowest[face], plate.level[k]);
      highest[face] = std::max<int> (highest[face], plate.level[k]);
    }
    if (lowest[0] == INT8_MAX || lowest[1] == INT8_MAX)
      continue;
    ++across;
    const auto below = [&] (int face) { return highest[face] <= 0 && lowest[face] < 0; };
    const auto above = [&] (int face) { return lowest[face] >= 0 && highest[face] > 0; };
    EXPECT_TRUE ((below (0) && above (1)) || (below (1) && above (0)))
        << "centre " << plate.centres[i] << ": bottom " << lowest[0] << ".." << highest[0] << ", top " << lowest[1]
        << ".." << highest[1];
  }
  EXPECT_GT (across, 0);
}

} // namespace
/** Two slabs of 12 x 12 x 3 voxels, one above the other, joined by a bar one voxel wide and three
  * long (x and y 5 to 6, z 3 to 6): a surface of genus 0. */
std::vector<Triangle>
slabsJoinedByABar ()
{
  return voxelBoundary (12, 9, [] (int x, int y, int z) { return z < 3 || z >= 6 || (x == 5 && y == 5); });
}

/** The grid corners of voxelBoundary (12, ...) as positions, those along the bar's middle moved
  * out from its axis by \a bulge in x and in y. */
std::vector<std::array<double, 3>>
slabPositions (double bulge)
{
  std::vector<std::array<double, 3>> positions (13 * 13 * 10);
  for (std::uint32_t v = 0; v < positions.size (); ++v)
  {
    const std::array<int, 3> c = voxelCorner (v, 12);
    positions[v] = {double (c[0]), double (c[1]), double (c[2])};
    if (c[2] > 3 && c[2] < 6 && (c[0] == 5 || c[0] == 6) && (c[1] == 5 || c[1] == 6))
      for (int i = 0; i < 2; ++i)
        positions[v][i] += c[i] == 5 ? -bulge : bulge;
  }
  return positions;
}

TEST (SurfaceHandles, ABarBetweenTwoPartsIsFoundAtItsSharpSaddles)
{
  // Where the bar, bulging, meets a slab, the angles at each of its four corners add up to
  // 2 pi + 0.68 pi: the patches next to them go round the bar, and its surface opens out past
  // both ends. Without positions the surface, of genus 0, is not looked at.
  const std::vector<Triangle> triangles = slabsJoinedByABar ();
  const auto num_vertices = static_cast<std::uint32_t> (13 * 13 * 10);
  EXPECT_TRUE (detail::smallHandlePatches (triangles, num_vertices).centres.empty ());
  const std::vector<std::array<double, 3>> positions = slabPositions (0.3);
  const detail::SmallHandlePatches bar = detail::smallHandlePatches (triangles, num_vertices, nullptr, &positions);
  ASSERT_FALSE (bar.centres.empty ());
  for (std::size_t i = 0; i < bar.centres.size (); ++i)
  {
    EXPECT_TRUE (bar.tunnel[i]);
    const std::array<int, 3> c = voxelCorner (bar.centres[i], 12);
    EXPECT_TRUE (c[0] >= 4 && c[0] <= 7 && c[1] >= 4 && c[1] <= 7 && c[2] >= 3 && c[2] <= 6)
        << c[0] << " " << c[1] << " " << c[2];
  }
  // The angles do not change with the scale: at coordinates of 2^600 and of 2^-600 (whose
  // differences' squares overflow and underflow) the same patches are found.
  for (const double scale : {0x1p600, 0x1p-600})
  {
    std::vector<std::array<double, 3>> scaled = positions;
    for (std::array<double, 3>& p : scaled)
      for (double& c : p)
        c *= scale;
    const detail::SmallHandlePatches same = detail::smallHandlePatches (triangles, num_vertices, nullptr, &scaled);
    EXPECT_EQ (same.centres, bar.centres) << scale;
    EXPECT_EQ (same.vertices, bar.vertices) << scale;
  }
  // A slab alone has no sharp saddle.
  const std::vector<Triangle> slab = voxelBoundary (12, 3, [] (int, int, int) { return true; });
  EXPECT_TRUE (detail::smallHandlePatches (slab, num_vertices, nullptr, &positions).centres.empty ());
}

} // namespace pcl_wrap::test
