// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

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

/** \brief Writes a triangle mesh whose vertices are \a points in order, by extension: .ply
  * (binary, double coordinates), .obj, .vtk (legacy ASCII) or .off (ASCII, double coordinates),
  * or .stl (binary; each triangle's corners and normal in float, no shared vertices, as the format
  * has it). Non-finite points are written as they are: triangles never use them.
  * \throws FileError when the file cannot be written */
void
writeMesh (const std::string& path, const std::vector<Point3>& points,
           const std::vector<std::array<PointIndex, 3>>& triangles);

} // namespace pcl_wrap::apps
