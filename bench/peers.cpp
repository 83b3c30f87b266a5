// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "peers.h"

#include "bench_points.h"

#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Regular_triangulation_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/alpha_wrap_3.h>

#include <pcl/common/io.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/surface/concave_hull.h>
#include <pcl/surface/gp3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace pcl_wrap::bench
{
namespace
{

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

std::vector<K::Point_3>
cgalPoints (const std::vector<Point3>& points)
{
  std::vector<K::Point_3> p;
  p.reserve (points.size ());
  for (const auto& q : points)
    p.emplace_back (q[0], q[1], q[2]);
  return p;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
pclCloud (const std::vector<Point3>& points)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  cloud->reserve (points.size ());
  for (const auto& q : points)
    cloud->push_back (pcl::PointXYZ (float (q[0]), float (q[1]), float (q[2])));
  return cloud;
}

PeerOutput
floorDelaunay (const std::vector<Point3>& points)
{
  const auto p = cgalPoints (points);
  CGAL::Delaunay_triangulation_3<K> dt (p.begin (), p.end ());
  PeerOutput out;
  out.note = std::to_string (dt.number_of_finite_cells ()) + " cells";
  return out;
}

PeerOutput
floorRegular (const std::vector<Point3>& points)
{
  std::vector<K::Weighted_point_3> p;
  p.reserve (points.size ());
  for (const auto& q : points)
    p.emplace_back (K::Point_3 (q[0], q[1], q[2]), 0.0);
  CGAL::Regular_triangulation_3<K> rt (p.begin (), p.end ());
  PeerOutput out;
  out.note = std::to_string (rt.number_of_finite_cells ()) + " cells";
  return out;
}

PeerOutput
wrapWith (const std::vector<Point3>& points, WrapParameters parameters, const std::string& note)
{
  parameters.keep_complex = false;
  const WrapResult r = computeWrap (points, parameters);
  PeerOutput out;
  out.vertices = points;
  for (const PointIndex i : r.copies) // vertices split where the surface touches itself
    out.vertices.push_back (points[i]);
  out.triangles = r.surface.triangles;
  out.note = note;
  for (const auto& t : r.statistics.timings)
    out.stages.emplace_back (t.stage, t.seconds);
  return out;
}

PeerOutput
wrap (const std::vector<Point3>& points)
{
  return wrapWith (points, WrapParameters (), "no parameters");
}

/** pcl_wrap's raw output: the paper's W = Bd X, with no parameters. */
PeerOutput
wrapRaw (const std::vector<Point3>& points)
{
  WrapParameters parameters;
  parameters.output = Output::raw;
  return wrapWith (points, parameters, "raw W");
}

/** pcl_wrap wrapping tighter: front deletion of the sinks wider than 4 x the spacing. */
PeerOutput
wrapFront (const std::vector<Point3>& points)
{
  WrapParameters parameters;
  parameters.threshold = Threshold::relativeRadius (4);
  return wrapWith (points, parameters, "front deletion, radius-rel 4");
}

PeerOutput
advancingFront (const std::vector<Point3>& points)
{
  const auto p = cgalPoints (points);
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction (p.begin (), p.end (), std::back_inserter (facets));
  PeerOutput out;
  out.vertices = points;
  for (const auto& f : facets)
    out.triangles.push_back ({std::uint32_t (f[0]), std::uint32_t (f[1]), std::uint32_t (f[2])});
  out.note = "defaults (radius_ratio_bound 5, beta pi/6)";
  return out;
}

PeerOutput
alphaWrapWith (const std::vector<Point3>& points, double alpha, double offset, const std::string& note)
{
  const auto p = cgalPoints (points);
  CGAL::Surface_mesh<K::Point_3> mesh;
  CGAL::alpha_wrap_3 (p, alpha, offset, mesh);
  PeerOutput out;
  std::map<CGAL::Surface_mesh<K::Point_3>::Vertex_index, std::uint32_t> index;
  for (const auto v : mesh.vertices ())
  {
    index[v] = std::uint32_t (out.vertices.size ());
    const auto& q = mesh.point (v);
    out.vertices.push_back ({q.x (), q.y (), q.z ()});
  }
  for (const auto f : mesh.faces ())
  {
    std::array<std::uint32_t, 3> t{};
    int i = 0;
    for (const auto v : CGAL::vertices_around_face (mesh.halfedge (f), mesh))
      if (i < 3)
        t[i++] = index[v];
    out.triangles.push_back (t);
  }
  out.note = note + "alpha " + std::to_string (alpha) + ", offset " + std::to_string (offset);
  return out;
}

PeerOutput
alphaWrap (const std::vector<Point3>& points)
{
  // The values of CGAL's own example: alpha = diagonal / 20, offset = diagonal / 600; and a
  // finer alpha = 10 x the spacing, closer to the points' detail, whichever is smaller.
  const double diag = boundingBoxDiagonal (points);
  return alphaWrapWith (points, std::min (diag / 20.0, 10.0 * medianSpacing (points)), diag / 600.0, "");
}

PeerOutput
alphaShape (const std::vector<Point3>& points)
{
  using Vb = CGAL::Alpha_shape_vertex_base_3<K, CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>>;
  using Fb = CGAL::Alpha_shape_cell_base_3<K>;
  using Tds = CGAL::Triangulation_data_structure_3<Vb, Fb>;
  using Triangulation = CGAL::Delaunay_triangulation_3<K, Tds, CGAL::Fast_location>;
  using AlphaShape = CGAL::Alpha_shape_3<Triangulation>;
  std::vector<std::pair<K::Point_3, std::uint32_t>> p;
  for (std::uint32_t i = 0; i < points.size (); ++i)
    p.emplace_back (K::Point_3 (points[i][0], points[i][1], points[i][2]), i);
  Triangulation dt (p.begin (), p.end ());
  AlphaShape shape (dt, 0, AlphaShape::REGULARIZED);
  // The optimal alpha: the smallest for which the solid is one component (CGAL's definition).
  const auto optimal = shape.find_optimal_alpha (1);
  shape.set_alpha (*optimal);
  std::vector<AlphaShape::Facet> facets;
  shape.get_alpha_shape_facets (std::back_inserter (facets), AlphaShape::REGULAR);
  PeerOutput out;
  out.vertices = points;
  for (auto f : facets)
  {
    // Orient away from the interior cell.
    if (shape.classify (f.first) != AlphaShape::INTERIOR)
      f = shape.mirror_facet (f);
    std::array<std::uint32_t, 3> t{};
    std::array<K::Point_3, 3> q;
    for (int i = 0, k = 0; i < 4; ++i)
      if (i != f.second)
      {
        t[k] = f.first->vertex (i)->info ();
        q[k++] = f.first->vertex (i)->point ();
      }
    if (CGAL::orientation (q[0], q[1], q[2], f.first->vertex (f.second)->point ()) == CGAL::POSITIVE)
      std::swap (t[1], t[2]); // the normal pointed into the solid
    out.triangles.push_back (t);
  }
  out.note = "optimal alpha " + std::to_string (CGAL::to_double (*optimal));
  return out;
}

/** The output of a PCL reconstruction: its cloud's points and triangles. */
PeerOutput
fromPcl (const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<pcl::Vertices>& polygons)
{
  PeerOutput out;
  for (const auto& q : cloud)
    out.vertices.push_back ({q.x, q.y, q.z});
  for (const auto& polygon : polygons)
    for (std::size_t i = 1; i + 1 < polygon.vertices.size (); ++i) // fans, should any be larger
      out.triangles.push_back ({std::uint32_t (polygon.vertices[0]), std::uint32_t (polygon.vertices[i]),
                                std::uint32_t (polygon.vertices[i + 1])});
  return out;
}

PeerOutput
concaveHull (const std::vector<Point3>& points)
{
  const double alpha = 2.0 * medianSpacing (points);
  pcl::ConcaveHull<pcl::PointXYZ> hull;
  hull.setInputCloud (pclCloud (points));
  hull.setAlpha (alpha);
  hull.setDimension (3);
  pcl::PointCloud<pcl::PointXYZ> cloud;
  std::vector<pcl::Vertices> polygons;
  hull.reconstruct (cloud, polygons);
  PeerOutput out = fromPcl (cloud, polygons);
  out.note = "alpha " + std::to_string (alpha) + " (2 x spacing)";
  return out;
}

PeerOutput
greedyProjection (const std::vector<Point3>& points)
{
  // PCL's tutorial: normals from 20 neighbours, then GP3 with mu 2.5 and 100 neighbours; its
  // search radius here is 5 x the spacing (the tutorial's 0.025 is for one scan's scale).
  const auto cloud = pclCloud (points);
  const auto start = std::chrono::steady_clock::now ();
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> estimation;
  auto tree = pcl::make_shared<pcl::search::KdTree<pcl::PointXYZ>> ();
  estimation.setInputCloud (cloud);
  estimation.setSearchMethod (tree);
  estimation.setKSearch (20);
  pcl::PointCloud<pcl::Normal> normals;
  estimation.compute (normals);
  auto with_normals = pcl::make_shared<pcl::PointCloud<pcl::PointNormal>> ();
  pcl::concatenateFields (*cloud, normals, *with_normals);
  const double normal_seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();

  const double radius = 5.0 * medianSpacing (points);
  pcl::GreedyProjectionTriangulation<pcl::PointNormal> gp3;
  auto tree2 = pcl::make_shared<pcl::search::KdTree<pcl::PointNormal>> ();
  tree2->setInputCloud (with_normals);
  gp3.setSearchRadius (radius);
  gp3.setMu (2.5);
  gp3.setMaximumNearestNeighbors (100);
  gp3.setMaximumSurfaceAngle (M_PI / 4);
  gp3.setMinimumAngle (M_PI / 18);
  gp3.setMaximumAngle (2 * M_PI / 3);
  gp3.setNormalConsistency (false);
  gp3.setInputCloud (with_normals);
  gp3.setSearchMethod (tree2);
  std::vector<pcl::Vertices> polygons;
  gp3.reconstruct (polygons);
  PeerOutput out = fromPcl (*cloud, polygons);
  out.normal_seconds = normal_seconds;
  out.note = "normals k 20; radius " + std::to_string (radius) + " (5 x spacing), mu 2.5";
  return out;
}

} // namespace

const std::vector<std::pair<std::string, Peer>>&
peers ()
{
  static const std::vector<std::pair<std::string, Peer>> all = {
      {"floor_delaunay", floorDelaunay},       {"floor_regular", floorRegular},
      {"pcl_wrap", wrap},                      {"pcl_wrap_raw", wrapRaw},
      {"pcl_wrap_front", wrapFront},
      {"cgal_advancing_front", advancingFront},
      {"cgal_alpha_wrap", alphaWrap},          {"cgal_alpha_shape", alphaShape},
      {"pcl_concave_hull", concaveHull},       {"pcl_greedy_projection", greedyProjection}};
  return all;
}

std::optional<Peer>
alphaWrapAt (const std::string& method)
{
  // cgal_alpha_wrap:diag/D:alpha/R or cgal_alpha_wrap:spacing*S:alpha/R
  const std::string prefix = "cgal_alpha_wrap:";
  if (method.compare (0, prefix.size (), prefix) != 0)
    return std::nullopt;
  const std::size_t colon = method.find (":alpha/", prefix.size ());
  if (colon == std::string::npos)
    return std::nullopt;
  const std::string alpha = method.substr (prefix.size (), colon - prefix.size ());
  const double offset_ratio = std::stod (method.substr (colon + 7));
  const bool by_diagonal = alpha.compare (0, 5, "diag/") == 0;
  if (!by_diagonal && alpha.compare (0, 8, "spacing*") != 0)
    return std::nullopt;
  const double factor = std::stod (alpha.substr (by_diagonal ? 5 : 8));
  return Peer ([=] (const std::vector<Point3>& points) {
    // The scale comes from the points, inside the timing, as a user would compute it.
    const double a = by_diagonal ? boundingBoxDiagonal (points) / factor : factor * medianSpacing (points);
    return alphaWrapWith (points, a, a / offset_ratio, alpha + ": ");
  });
}

double
medianSpacing (const std::vector<Point3>& points)
{
  // As a PCL user sets these methods up: a k-d tree on the cloud, two neighbours per point.
  if (points.size () < 2)
    return 0.0;
  const auto cloud = pclCloud (points);
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  std::vector<double> nearest;
  pcl::Indices neighbours (2);
  std::vector<float> squared (2);
  for (const auto& q : *cloud)
    if (tree.nearestKSearch (q, 2, neighbours, squared) == 2)
      nearest.push_back (std::sqrt (double (squared[1])));
  if (nearest.empty ())
    return 0.0;
  std::nth_element (nearest.begin (), nearest.begin () + nearest.size () / 2, nearest.end ());
  return nearest[nearest.size () / 2];
}

} // namespace pcl_wrap::bench
