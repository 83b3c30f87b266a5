// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// mesh_quality MESH.obj POINTS REFERENCE [SAMPLES]: the quality of a reconstruction, as one JSON
// line. POINTS: the input (a file, or SHAPE:N:SEED as bench_peers makes it); REFERENCE: the
// true surface, "sphere", "torus", a mesh file (.off/.obj with faces: sampled by area),
// "points" (the input points themselves, for a scan without a mesh), or "none" (no distances:
// chamfer and hausdorff are -1).
//   chamfer, hausdorff: between SAMPLES points on the output (by area) and on the reference,
//     relative to the reference's bounding box diagonal (PCL k-d trees);
//   points_on_output: share of input points that are vertices of some triangle (in floats);
//   watertight: every edge in exactly two triangles; nonmanifold_edges (> 2 triangles),
//     boundary_edges (1), nonmanifold_vertices (triangles around it not one fan);
//   components (by shared edges), euler, genus (closed manifolds: (2 components - euler) / 2).
#include "errors_reported.h"
#include "bench_points.h"
#include "point_file.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace
{

using pcl_wrap::Point3;
using Triangle = std::array<std::uint32_t, 3>;

struct Mesh
{
  std::vector<Point3> vertices;
  std::vector<Triangle> triangles;
};

/** An OBJ or OFF file's vertices and triangles (polygons as fans). */
Mesh
readMesh (const std::string& path)
{
  Mesh m;
  std::ifstream in (path);
  if (!in)
    throw std::runtime_error (path + ": cannot open");
  std::string line;
  if (path.size () > 4 && path.substr (path.size () - 4) == ".off")
  {
    std::getline (in, line);
    std::size_t nv = 0, nf = 0, ne = 0;
    in >> nv >> nf >> ne;
    m.vertices.resize (nv);
    for (auto& v : m.vertices)
      in >> v[0] >> v[1] >> v[2];
    for (std::size_t f = 0; f < nf; ++f)
    {
      std::size_t k = 0;
      in >> k;
      std::vector<std::uint32_t> ids (k);
      for (auto& id : ids)
        in >> id;
      for (std::size_t i = 1; i + 1 < k; ++i)
        m.triangles.push_back ({ids[0], ids[i], ids[i + 1]});
    }
    return m;
  }
  while (std::getline (in, line))
  {
    std::istringstream s (line);
    std::string tag;
    s >> tag;
    if (tag == "v")
    {
      Point3 v{};
      s >> v[0] >> v[1] >> v[2];
      m.vertices.push_back (v);
    }
    else if (tag == "f")
    {
      std::vector<std::uint32_t> ids;
      std::string token;
      while (s >> token)
        ids.push_back (std::uint32_t (std::stoul (token.substr (0, token.find ('/')))) - 1);
      for (std::size_t i = 1; i + 1 < ids.size (); ++i)
        m.triangles.push_back ({ids[0], ids[i], ids[i + 1]});
    }
  }
  return m;
}

/** \a count points uniformly by area on the triangles. */
std::vector<Point3>
sampleSurface (const Mesh& m, std::size_t count, unsigned seed)
{
  std::vector<double> area (m.triangles.size ());
  for (std::size_t i = 0; i < m.triangles.size (); ++i)
  {
    const Point3 &a = m.vertices[m.triangles[i][0]], &b = m.vertices[m.triangles[i][1]],
                 &c = m.vertices[m.triangles[i][2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
    area[i] = 0.5 * std::sqrt (x * x + y * y + z * z);
  }
  std::vector<Point3> out;
  if (m.triangles.empty () || std::accumulate (area.begin (), area.end (), 0.0) <= 0)
    return out;
  std::mt19937_64 random (seed);
  std::discrete_distribution<std::size_t> pick (area.begin (), area.end ());
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  for (std::size_t k = 0; k < count; ++k)
  {
    const Triangle& t = m.triangles[pick (random)];
    double r1 = unit (random), r2 = unit (random);
    if (r1 + r2 > 1)
      r1 = 1 - r1, r2 = 1 - r2;
    Point3 p;
    for (int i = 0; i < 3; ++i)
      p[i] = m.vertices[t[0]][i] + r1 * (m.vertices[t[1]][i] - m.vertices[t[0]][i]) +
             r2 * (m.vertices[t[2]][i] - m.vertices[t[0]][i]);
    out.push_back (p);
  }
  return out;
}

/** Distances from each of \a from to the nearest of \a to: mean and max. */
std::pair<double, double>
nearestDistances (const std::vector<Point3>& from, const std::vector<Point3>& to)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (const auto& p : to)
    cloud->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  double sum = 0, max = 0;
  pcl::Indices k (1);
  std::vector<float> d (1);
  for (const auto& p : from)
  {
    tree.nearestKSearch (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])), 1, k, d);
    const double dist = std::sqrt (double (d[0]));
    sum += dist;
    max = std::max (max, dist);
  }
  return {from.empty () ? 0.0 : sum / double (from.size ()), max};
}


/** The reference surface sampled with \a count points. */
std::vector<Point3>
referenceSamples (const std::string& reference, const std::vector<Point3>& input, std::size_t count)
{
  std::mt19937_64 random (7);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> angle (0.0, 2 * M_PI), unit (0.0, 1.0);
  std::vector<Point3> out;
  if (reference == "points")
    return input;
  if (reference == "none")
    return out;
  if (reference == "sphere")
    for (std::size_t k = 0; k < count; ++k)
    {
      const double x = g (random), y = g (random), z = g (random), r = std::sqrt (x * x + y * y + z * z);
      out.push_back ({x / r, y / r, z / r});
    }
  else if (reference == "torus")
    while (out.size () < count) // uniform by area: accept the tube angle with weight (R + r cos b)
    {
      const double a = angle (random), b = angle (random);
      if (unit (random) * 1.4 > 1.0 + 0.4 * std::cos (b))
        continue;
      out.push_back (
          {(1.0 + 0.4 * std::cos (b)) * std::cos (a), (1.0 + 0.4 * std::cos (b)) * std::sin (a), 0.4 * std::sin (b)});
    }
  else
    out = sampleSurface (readMesh (reference), count, 7);
  return out;
}

} // namespace

static int
run (int argc, char** argv)
{
  if (argc < 4)
  {
    std::cerr << "usage: mesh_quality MESH.obj POINTS REFERENCE [SAMPLES]\n";
    return 2;
  }
  const Mesh mesh = readMesh (argv[1]);
  std::string points_spec = argv[2];
  std::vector<Point3> input;
  if (std::count (points_spec.begin (), points_spec.end (), ':') == 2)
  {
    const std::size_t a = points_spec.find (':'), b = points_spec.rfind (':');
    input = pcl_wrap::bench::makePoints (points_spec.substr (0, a), std::stoul (points_spec.substr (a + 1, b - a - 1)),
                                         unsigned (std::stoul (points_spec.substr (b + 1))));
  }
  else
    input = pcl_wrap::apps::readPointFile (points_spec).points;
  const std::size_t samples = argc > 4 ? std::stoul (argv[4]) : 200000;

  // Topology.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      ++edges[{std::min (t[i], t[(i + 1) % 3]), std::max (t[i], t[(i + 1) % 3])}];
  std::size_t nonmanifold_edges = 0, boundary_edges = 0;
  for (const auto& [e, n] : edges)
    nonmanifold_edges += n > 2, boundary_edges += n == 1;
  // Components by shared edges; fans per vertex by triangles sharing an edge at it.
  std::vector<std::uint32_t> parent (mesh.triangles.size ());
  std::iota (parent.begin (), parent.end (), 0u);
  const auto find = [&] (std::uint32_t a) {
    while (parent[a] != a)
      a = parent[a] = parent[parent[a]];
    return a;
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> first_on_edge;
  std::map<std::uint32_t, std::vector<std::uint32_t>> around;
  for (std::uint32_t f = 0; f < mesh.triangles.size (); ++f)
    for (int i = 0; i < 3; ++i)
    {
      const auto& t = mesh.triangles[f];
      around[t[i]].push_back (f);
      const std::pair<std::uint32_t, std::uint32_t> e{std::min (t[i], t[(i + 1) % 3]), std::max (t[i], t[(i + 1) % 3])};
      auto [it, fresh] = first_on_edge.emplace (e, f);
      if (!fresh)
        parent[find (f)] = find (it->second);
    }
  std::set<std::uint32_t> roots;
  for (std::uint32_t f = 0; f < mesh.triangles.size (); ++f)
    roots.insert (find (f));
  std::size_t nonmanifold_vertices = 0;
  for (const auto& [v, faces] : around)
  {
    // The triangles at v, joined across the edges at v: one fan unless v is a pinch.
    std::map<std::uint32_t, std::uint32_t> fan;
    for (std::uint32_t f : faces)
      fan[f] = f;
    const auto root = [&] (std::uint32_t a) {
      while (fan[a] != a)
        a = fan[a];
      return a;
    };
    std::map<std::uint32_t, std::uint32_t> by_other;
    for (std::uint32_t f : faces)
      for (std::uint32_t w : mesh.triangles[f])
        if (w != v)
        {
          auto [it, fresh] = by_other.emplace (w, f);
          if (!fresh)
            fan[root (f)] = root (it->second);
        }
    std::set<std::uint32_t> fans;
    for (std::uint32_t f : faces)
      fans.insert (root (f));
    nonmanifold_vertices += fans.size () > 1;
  }
  const long euler = long (around.size ()) - long (edges.size ()) + long (mesh.triangles.size ());
  const bool watertight = !mesh.triangles.empty () && nonmanifold_edges == 0 && boundary_edges == 0;

  // Input points on the output: vertices of a triangle at an input point's position, compared in
  // single precision (PCL's reconstructions work in floats).
  const auto single = [] (const Point3& p) { return std::array<float, 3>{float (p[0]), float (p[1]), float (p[2])}; };
  std::set<std::array<float, 3>> used;
  for (const auto& [v, faces] : around)
    used.insert (single (mesh.vertices[v]));
  std::size_t on_output = 0;
  for (const auto& p : input)
    on_output += used.count (single (p));

  // Distances.
  const double diag = pcl_wrap::bench::boundingBoxDiagonal (input);
  const std::vector<Point3> reference = referenceSamples (argv[3], input, samples);
  const std::vector<Point3> output = sampleSurface (mesh, samples, 11);
  double chamfer = -1, hausdorff = -1;
  if (!output.empty () && !reference.empty ())
  {
    const auto to_reference = nearestDistances (output, reference), to_output = nearestDistances (reference, output);
    chamfer = 0.5 * (to_reference.first + to_output.first) / diag;
    hausdorff = std::max (to_reference.second, to_output.second) / diag;
  }
  std::printf ("{\"triangles\":%zu,\"chamfer\":%.6g,\"hausdorff\":%.6g,\"points_on_output\":%.4f,\"watertight\":%s,"
               "\"nonmanifold_edges\":%zu,\"boundary_edges\":%zu,\"nonmanifold_vertices\":%zu,\"components\":%zu,"
               "\"euler\":%ld,\"genus\":%s}\n",
               mesh.triangles.size (), chamfer, hausdorff,
               input.empty () ? 0.0 : double (on_output) / double (input.size ()), watertight ? "true" : "false",
               nonmanifold_edges, boundary_edges, nonmanifold_vertices, roots.size (), euler,
               watertight && nonmanifold_vertices == 0
                   ? std::to_string ((2 * long (roots.size ()) - euler) / 2).c_str ()
                   : "null");
  return 0;
}

int
main (int argc, char** argv)
{
  return pcl_wrap::bench::errorsReported ("mesh_quality", run, argc, argv);
}
