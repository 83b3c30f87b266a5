// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "mesh_file.h"

#include "point_file.h"

#include <cerrno>
#include <cmath>
#include <cstdint>
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

void
writeOff (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles)
{
  out << "OFF\n# written by pcl_wrap\n" << points.size () << ' ' << triangles.size () << " 0\n";
  for (const Point3& p : points)
    out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for (const auto& t : triangles)
    out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

/** Binary STL: each triangle on its own, its corners and normal in float, as the format has it. */
void
writeStl (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles)
{
  char header[80] = "binary STL written by pcl_wrap";
  out.write (header, sizeof header);
  putBinary<std::uint32_t> (out, static_cast<std::uint32_t> (triangles.size ()));
  for (const auto& t : triangles)
  {
    const Point3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& x : n)
      putBinary (out, static_cast<float> (length > 0 ? x / length : 0.0));
    for (const Point3* corner : {&a, &b, &c})
      for (double x : *corner)
        putBinary (out, static_cast<float> (x));
    putBinary<std::uint16_t> (out, 0);
  }
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
  for (const char* extension : {".ply", ".obj", ".vtk", ".off", ".stl"})
    if (endsWith (path, extension))
      return true;
  return false;
}

void
writeMesh (const std::string& path, const std::vector<Point3>& points,
           const std::vector<std::array<PointIndex, 3>>& triangles)
{
  if (!isMeshFormat (path))
    throw FileError (path + ": unknown output format (expected .ply, .obj, .vtk, .off or .stl)");
  writeAtomically (path, [&] (std::ostream& out) {
    if (endsWith (path, ".ply"))
      writePly (out, points, triangles);
    else if (endsWith (path, ".obj"))
      writeObj (out, points, triangles);
    else if (endsWith (path, ".off"))
      writeOff (out, points, triangles);
    else if (endsWith (path, ".stl"))
      writeStl (out, points, triangles);
    else
      writeVtk (out, points, triangles);
  });
}

} // namespace pcl_wrap::apps
