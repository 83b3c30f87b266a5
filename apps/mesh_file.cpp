// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "mesh_file.h"

#include "point_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <unistd.h>

namespace pcl_wrap::apps
{
namespace
{

bool
endsWith (const std::string& s, const std::string& suffix)
{
  return s.size () >= suffix.size () && s.compare (s.size () - suffix.size (), suffix.size (), suffix) == 0;
}

template <class T>
void
putBinary (std::ostream& out, T value)
{
  out.write (reinterpret_cast<const char*> (&value), sizeof (T)); // little endian on every target we build for
}

void
writePly (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles)
{
  out << "ply\nformat binary_little_endian 1.0\ncomment written by pcl_wrap\n"
      << "element vertex " << points.size () << "\nproperty double x\nproperty double y\nproperty double z\n"
      << "element face " << triangles.size () << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const Point3& p : points)
    for (double c : p)
      putBinary (out, c);
  for (const auto& t : triangles)
  {
    putBinary<std::uint8_t> (out, 3);
    for (PointIndex v : t)
      putBinary<std::int32_t> (out, static_cast<std::int32_t> (v));
  }
}

void
writeObj (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles)
{
  out << "# written by pcl_wrap\n";
  for (const Point3& p : points)
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : triangles)
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

void
writeVtk (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles)
{
  out << "# vtk DataFile Version 3.0\nwritten by pcl_wrap\nASCII\nDATASET POLYDATA\nPOINTS " << points.size ()
      << " double\n";
  for (const Point3& p : points)
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  out << "POLYGONS " << triangles.size () << ' ' << 4 * triangles.size () << '\n';
  for (const auto& t : triangles)
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

} // namespace

void
writeAtomically (const std::string& path, const std::function<void (std::ostream&)>& write)
{
  const std::string temporary = path + ".tmp" + std::to_string (::getpid ());
  {
    std::ofstream out (temporary, std::ios::binary);
    if (!out)
      throw FileError (path + ": cannot write: " + std::strerror (errno));
    out.precision (std::numeric_limits<double>::max_digits10);
    write (out);
    out.flush ();
    if (!out)
    {
      std::remove (temporary.c_str ());
      throw FileError (path + ": write failed (disk full?)");
    }
  }
  if (std::rename (temporary.c_str (), path.c_str ()) != 0)
  {
    const std::string why = std::strerror (errno);
    std::remove (temporary.c_str ());
    throw FileError (path + ": cannot write: " + why);
  }
}

bool
isMeshFormat (const std::string& path)
{
  return endsWith (path, ".ply") || endsWith (path, ".obj") || endsWith (path, ".vtk");
}

void
writeMesh (const std::string& path, const std::vector<Point3>& points,
           const std::vector<std::array<PointIndex, 3>>& triangles)
{
  if (!isMeshFormat (path))
    throw FileError (path + ": unknown output format (expected .ply, .obj or .vtk)");
  writeAtomically (path, [&] (std::ostream& out) {
    if (endsWith (path, ".ply"))
      writePly (out, points, triangles);
    else if (endsWith (path, ".obj"))
      writeObj (out, points, triangles);
    else
      writeVtk (out, points, triangles);
  });
}

} // namespace pcl_wrap::apps
