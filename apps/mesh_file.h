// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "point_attributes.h"

#include <pcl_wrap/compute_wrap.h>

#include <array>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace pcl_wrap::apps
{

/** \brief Writes a file atomically: \a write fills a temporary file beside \a path, which is
  * renamed to \a path only when everything was written. No partial file is ever left.
  * \throws FileError when the file cannot be written */
void
writeAtomically (const std::string& path, const std::function<void (std::ostream&)>& write);

/** \brief Is \a path's extension one writeMesh() knows (.ply, .obj, .vtk, .off, .stl)? */
bool
isMeshFormat (const std::string& path);

/** \brief Writes a triangle mesh whose vertices are \a points in order, with their \a attributes
  * (empty, or one entry per point), by extension:
  * - .ply (binary, double coordinates): normals as nx ny nz, colours as red green blue [alpha],
  *   every other field as a property of its own type;
  * - .vtk (legacy ASCII): normals, colours and every field as point data;
  * - .obj: colours as "v x y z r g b" (0 to 1), normals as "vn" (faces "f a//a b//b c//c");
  * - .off (ASCII, double coordinates): normals and colours as NOFF, COFF or CNOFF;
  * - .stl (binary; each triangle's corners and normal in float, no shared vertices, as the format
  *   has it): no attributes.
  * Fields a format has no place for are not written.
  * \throws FileError when the file cannot be written */
void
writeMesh (const std::string& path, const std::vector<Point3>& points,
           const std::vector<std::array<PointIndex, 3>>& triangles,
           const PointAttributes& attributes = PointAttributes ());

/** \brief What of \a attributes a mesh file \a path keeps: "colours, normals" or "" (for the
  * user to know, next to PointAttributes::describe()). */
std::string
attributesKeptBy (const std::string& path, const PointAttributes& attributes);

} // namespace pcl_wrap::apps
