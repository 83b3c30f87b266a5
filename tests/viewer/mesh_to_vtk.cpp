// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// mesh_to_vtk IN.ply OUT.vtk: a mesh through PCL's PLY reader into a legacy VTK file for
// pcl_viewer, which opens only .pcd and .vtk (PCL's pcl_ply2obj and saveVTKFile take single
// precision only; pcl_wrap writes doubles).
#include <pcl_wrap/point_field.h>

#include <pcl/PolygonMesh.h>
#include <pcl/io/ply_io.h>

#include <cstdio>
#include <fstream>
#include <string>

int
main (int argc, char** argv)
{
  if (argc != 3)
  {
    std::fprintf (stderr, "usage: mesh_to_vtk IN.ply OUT.vtk\n");
    return 2;
  }
  pcl::PolygonMesh mesh;
  if (pcl::io::loadPLYFile (argv[1], mesh) < 0 || mesh.polygons.empty ())
  {
    std::fprintf (stderr, "mesh_to_vtk: cannot read a mesh from %s\n", argv[1]);
    return 1;
  }
  const std::vector<double> x = pcl_wrap::readFieldValues (mesh.cloud, "x"),
                            y = pcl_wrap::readFieldValues (mesh.cloud, "y"),
                            z = pcl_wrap::readFieldValues (mesh.cloud, "z");
  std::ofstream out (argv[2]);
  out.precision (17);
  out << "# vtk DataFile Version 3.0\nthrough PCL's PLY reader\nASCII\nDATASET POLYDATA\nPOINTS " << x.size ()
      << " double\n";
  for (std::size_t i = 0; i < x.size (); ++i)
    out << x[i] << ' ' << y[i] << ' ' << z[i] << '\n';
  out << "POLYGONS " << mesh.polygons.size () << ' ' << 4 * mesh.polygons.size () << '\n';
  for (const auto& polygon : mesh.polygons)
    out << "3 " << polygon.vertices[0] << ' ' << polygon.vertices[1] << ' ' << polygon.vertices[2] << '\n';
  return out ? 0 : 1;
}
