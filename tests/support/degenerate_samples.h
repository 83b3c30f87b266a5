// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// Point sets that are not in general position, as scanners, CAD exports and quantisation make
// them: grids, cospherical and coplanar sets, duplicates, extreme magnitudes.
#include "samplers.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace pcl_wrap::test
{

/** nx x ny x nz integer grid with spacings (sx, sy, sz); x also moves by shear * z. */
inline std::vector<Point3>
gridSample (int nx, int ny, int nz, double sx = 1, double sy = 1, double sz = 1, double shear = 0)
{
  std::vector<Point3> p;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k)
        p.push_back ({i * sx + shear * k, j * sy, k * sz});
  return p;
}

/** Every integer point on the sphere x^2 + y^2 + z^2 = r2: many exactly cospherical subsets,
  * and exactly coplanar ones. */
inline std::vector<Point3>
integerSphereSample (int r2)
{
  std::vector<Point3> p;
  const int r = static_cast<int> (std::sqrt (double (r2)));
  for (int x = -r; x <= r; ++x)
    for (int y = -r; y <= r; ++y)
      for (int z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r2)
          p.push_back ({double (x), double (y), double (z)});
  return p;
}

/** The regular polyhedra's vertices (cospherical; exactly for the tetrahedron, octahedron and
  * cube, to double precision for the icosahedron and dodecahedron). */
inline std::vector<std::vector<Point3>>
regularPolyhedra ()
{
  const double f = (1.0 + std::sqrt (5.0)) / 2.0, g = 1.0 / f;
  std::vector<Point3> tetrahedron = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  std::vector<Point3> octahedron = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<Point3> cube, icosahedron, dodecahedron;
  for (int s = 0; s < 8; ++s)
  {
    const double a = s & 1 ? -1 : 1, b = s & 2 ? -1 : 1, c = s & 4 ? -1 : 1;
    cube.push_back ({a, b, c});
    dodecahedron.push_back ({a, b, c});
  }
  for (int s = 0; s < 4; ++s)
  {
    const double a = s & 1 ? -1 : 1, b = s & 2 ? -1 : 1;
    icosahedron.insert (icosahedron.end (), {{0, a, b * f}, {a, b * f, 0}, {b * f, 0, a}});
    dodecahedron.insert (dodecahedron.end (), {{0, a * g, b * f}, {a * g, b * f, 0}, {b * f, 0, a * g}});
  }
  return {tetrahedron, octahedron, cube, icosahedron, dodecahedron};
}

struct NamedSample
{
  std::string name;
  std::vector<Point3> points;
};

/** Every degenerate family the suite covers, with a name for test traces. */
inline std::vector<NamedSample>
degenerateFamilies ()
{
  std::vector<NamedSample> f;
  f.push_back ({"grid 6x6x6", gridSample (6, 6, 6)});
  f.push_back ({"anisotropic grid", gridSample (7, 4, 5, 1.0, 0.25, 3.0)});
  f.push_back ({"sheared grid", gridSample (5, 5, 5, 1.0, 1.0, 1.0, 0.5)});
  auto corners = gridSample (2, 2, 2);
  f.push_back ({"cube corners", corners});
  corners.push_back ({0.5, 0.5, 0.5});
  f.push_back ({"cube corners and centre", corners});
  const char* names[] = {"tetrahedron", "octahedron", "cube", "icosahedron", "dodecahedron"};
  const auto polyhedra = regularPolyhedra ();
  for (int i = 0; i < 5; ++i)
    f.push_back ({names[i], polyhedra[i]});
  f.push_back ({"integer sphere r2=50", integerSphereSample (50)});
  f.push_back ({"integer sphere r2=101", integerSphereSample (101)});
  f.push_back ({"planar grid", gridSample (8, 6, 1)});
  f.push_back ({"collinear", gridSample (9, 1, 1)});
  f.push_back ({"one point", {{1, 2, 3}}});
  f.push_back ({"two points", {{1, 2, 3}, {1, 2, 4}}});
  f.push_back ({"three points", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}});
  std::vector<Point3> copies;
  for (int i = 0; i < 60; ++i)
    copies.push_back (gridSample (2, 2, 2)[i % 5]);
  f.push_back ({"many copies of five points", copies});
  std::vector<Point3> huge, tiny;
  for (const auto& p : gridSample (4, 4, 4))
  {
    huge.push_back ({1e9 + p[0], 1e9 + 2 * p[1], 1e9 + p[2]});
    tiny.push_back ({1e-9 * p[0], 1e-9 * p[1], 3e-9 * p[2]});
  }
  f.push_back ({"grid around 1e9", huge});
  f.push_back ({"grid of 1e-9", tiny});
  auto mixed = gridSample (4, 4, 4);
  for (const auto& p : cubeSample (60, 3))
    mixed.push_back ({1.5 + 1.5 * p[0], 1.5 + 1.5 * p[1], 1.5 + 1.5 * p[2]});
  for (const auto& p : integerSphereSample (50))
    mixed.push_back (p);
  f.push_back ({"grid, sphere and random points", mixed});
  return f;
}

} // namespace pcl_wrap::test
