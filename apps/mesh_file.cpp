// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "mesh_file.h"

#include "number_text.h"
#include "point_file.h"

#include <cctype>
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

const char*
plyType (std::uint8_t datatype)
{
  static const char* const NAMES[] = {"", "char", "uchar", "short", "ushort", "int", "uint", "float", "double"};
  return datatype >= 1 && datatype <= 8 ? NAMES[datatype] : "double";
}

/** A field's value, as its PLY type, in binary. */
void
putScalar (std::ostream& out, std::uint8_t datatype, double value)
{
  switch (datatype)
  {
  case 1: putBinary (out, static_cast<std::int8_t> (value)); break;
  case 2: putBinary (out, static_cast<std::uint8_t> (value)); break;
  case 3: putBinary (out, static_cast<std::int16_t> (value)); break;
  case 4: putBinary (out, static_cast<std::uint16_t> (value)); break;
  case 5: putBinary (out, static_cast<std::int32_t> (value)); break;
  case 6: putBinary (out, static_cast<std::uint32_t> (value)); break;
  case 7: putBinary (out, static_cast<float> (value)); break;
  default: putBinary (out, value); break;
  }
}

/** A name a format's header can carry: no whitespace. */
std::string
headerName (std::string name)
{
  for (char& c : name)
    if (std::isspace (static_cast<unsigned char> (c)))
      c = '_';
  return name;
}

void
writePly (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles,
          const PointAttributes& a)
{
  out << "ply\nformat binary_little_endian 1.0\ncomment written by pcl_wrap\n"
      << "element vertex " << points.size () << "\nproperty double x\nproperty double y\nproperty double z\n";
  if (!a.normals.empty ())
    out << "property float nx\nproperty float ny\nproperty float nz\n";
  if (!a.colours.empty ())
    out << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
        << (a.alpha ? "property uchar alpha\n" : "");
  for (const ScalarField& f : a.scalars)
    out << "property " << plyType (f.datatype) << ' ' << headerName (f.name) << '\n';
  out << "element face " << triangles.size () << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    for (double c : points[i])
      putBinary (out, c);
    if (!a.normals.empty ())
      for (float c : a.normals[i])
        putBinary (out, c);
    if (!a.colours.empty ())
      out.write (reinterpret_cast<const char*> (a.colours[i].data ()), a.alpha ? 4 : 3);
    for (const ScalarField& f : a.scalars)
      putScalar (out, f.datatype, f.values[i]);
  }
  for (const auto& t : triangles)
  {
    putBinary<std::uint8_t> (out, 3);
    for (PointIndex v : t)
      putBinary<std::int32_t> (out, static_cast<std::int32_t> (v));
  }
}

/** "x y z": three numbers as a stream writes them (a float widened to double). */
template <class T>
void
appendTriple (std::string& text, const std::array<T, 3>& values)
{
  for (int k = 0; k < 3; ++k)
  {
    if (k > 0)
      text += ' ';
    appendReal (text, values[k]);
  }
}

void
writeObj (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles,
          const PointAttributes& a)
{
  out << "# written by pcl_wrap\n";
  writeInParallel (out, points.size (), [&] (std::size_t i, std::string& text) {
    text += "v ";
    appendTriple (text, points[i]);
    if (!a.colours.empty ())
      for (int k = 0; k < 3; ++k)
      {
        text += ' ';
        appendReal (text, a.colours[i][k] / 255.0);
      }
    text += '\n';
  });
  writeInParallel (out, a.normals.size (), [&] (std::size_t i, std::string& text) {
    text += "vn ";
    appendTriple (text, a.normals[i]);
    text += '\n';
  });
  writeInParallel (out, triangles.size (), [&] (std::size_t i, std::string& text) {
    text += 'f';
    for (PointIndex v : triangles[i])
    {
      text += ' ';
      appendInteger (text, v + 1ll);
      if (!a.normals.empty ())
      {
        text += "//";
        appendInteger (text, v + 1ll);
      }
    }
    text += '\n';
  });
}

/** "3 a b c\n" per triangle: the faces of a .vtk or .off file. */
void
writeTriangles (std::ostream& out, const std::vector<std::array<PointIndex, 3>>& triangles)
{
  writeInParallel (out, triangles.size (), [&] (std::size_t i, std::string& text) {
    text += '3';
    for (PointIndex v : triangles[i])
    {
      text += ' ';
      appendInteger (text, v);
    }
    text += '\n';
  });
}

void
writeVtk (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles,
          const PointAttributes& a)
{
  out << "# vtk DataFile Version 3.0\nwritten by pcl_wrap\nASCII\nDATASET POLYDATA\nPOINTS " << points.size ()
      << " double\n";
  writeInParallel (out, points.size (), [&] (std::size_t i, std::string& text) {
    appendTriple (text, points[i]);
    text += '\n';
  });
  out << "POLYGONS " << triangles.size () << ' ' << 4 * triangles.size () << '\n';
  writeTriangles (out, triangles);
  if (a.empty ())
    return;
  out << "POINT_DATA " << points.size () << '\n';
  if (!a.normals.empty ())
  {
    out << "NORMALS normals float\n";
    writeInParallel (out, a.normals.size (), [&] (std::size_t i, std::string& text) {
      appendTriple (text, a.normals[i]);
      text += '\n';
    });
  }
  // First: a reader that takes one set of scalars (VTK's by default: PCL, pcl_viewer) takes these.
  if (!a.colours.empty ())
  {
    const int components = a.alpha ? 4 : 3;
    out << "COLOR_SCALARS " << (a.alpha ? "RGBA " : "RGB ") << components << '\n'; // PCL reads "RGB"
    writeInParallel (out, a.colours.size (), [&] (std::size_t i, std::string& text) {
      for (int k = 0; k < components; ++k)
      {
        appendReal (text, a.colours[i][k] / 255.0);
        text += k + 1 < components ? ' ' : '\n';
      }
    });
  }
  for (const ScalarField& f : a.scalars)
  {
    out << "SCALARS " << headerName (f.name) << " double 1\nLOOKUP_TABLE default\n";
    writeInParallel (out, f.values.size (), [&] (std::size_t i, std::string& text) {
      appendReal (text, f.values[i]);
      text += '\n';
    });
  }
}

void
writeOff (std::ostream& out, const std::vector<Point3>& points, const std::vector<std::array<PointIndex, 3>>& triangles,
          const PointAttributes& a)
{
  out << (a.colours.empty () ? "" : "C") << (a.normals.empty () ? "" : "N") << "OFF\n# written by pcl_wrap\n"
      << points.size () << ' ' << triangles.size () << " 0\n";
  writeInParallel (out, points.size (), [&] (std::size_t i, std::string& text) {
    appendTriple (text, points[i]);
    if (!a.normals.empty ())
    {
      text += ' ';
      appendTriple (text, a.normals[i]);
    }
    if (!a.colours.empty ()) // whole numbers: 0 to 255, as the format reads them
      for (int k = 0; k < 4; ++k)
      {
        text += ' ';
        appendInteger (text, a.colours[i][k]);
      }
    text += '\n';
  });
  writeTriangles (out, triangles);
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
           const std::vector<std::array<PointIndex, 3>>& triangles, const PointAttributes& attributes)
{
  if (!isMeshFormat (path))
    throw FileError (path + ": unknown output format (expected .ply, .obj, .vtk, .off or .stl)");
  writeAtomically (path, [&] (std::ostream& out) {
    if (endsWith (path, ".ply"))
      writePly (out, points, triangles, attributes);
    else if (endsWith (path, ".obj"))
      writeObj (out, points, triangles, attributes);
    else if (endsWith (path, ".off"))
      writeOff (out, points, triangles, attributes);
    else if (endsWith (path, ".stl"))
      writeStl (out, points, triangles);
    else
      writeVtk (out, points, triangles, attributes);
  });
}

std::string
attributesKeptBy (const std::string& path, const PointAttributes& attributes)
{
  PointAttributes kept = attributes;
  if (endsWith (path, ".stl"))
    kept = PointAttributes ();
  if (endsWith (path, ".obj") || endsWith (path, ".off"))
    kept.scalars.clear ();
  if (endsWith (path, ".obj"))
    kept.alpha = false;
  return kept.describe ();
}

} // namespace pcl_wrap::apps
