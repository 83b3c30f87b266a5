// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap::Wrap as a PCL stage: NaNs and setIndices in, a PolygonMesh indexing the input cloud
// out, through PCL's PLY writer and reader.
#include "support/pcl_mesh.h"
#include "support/samplers.h"
#include "support/topology.h"

#include <pcl_wrap/wrap.h>

#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <set>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

TEST (PclWrap, CloudWithNansAndIndicesToPolygonMeshAndBackThroughPly)
{
  // A sphere (every other point selected), with NaNs among the selected and unselected points.
  const auto sample = sphereSample (1200, 9, 1e-3);
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (const auto& p : sample)
    cloud->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  const float nan = std::numeric_limits<float>::quiet_NaN ();
  for (std::size_t i : {4u, 6u, 7u, 100u})
    (*cloud)[i].x = nan;
  cloud->is_dense = false;
  auto indices = pcl::make_shared<pcl::Indices> ();
  for (int i = 0; i < int (cloud->size ()); i += 2)
    indices->push_back (i);

  Wrap<pcl::PointXYZ> wrap;
  wrap.setInputCloud (cloud);
  wrap.setIndices (indices);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);

  // PCL's convention: the output cloud is the whole input; polygons index it.
  EXPECT_EQ (std::size_t (mesh.cloud.width) * mesh.cloud.height, cloud->size ());
  const WrapStatistics& stats = wrap.getStatistics ();
  EXPECT_EQ (stats.points_input, indices->size ());
  EXPECT_EQ (stats.points_skipped, 3u); // 4, 6 and 100 are selected; 7 is not
  EXPECT_EQ (wrap.getResult ().skipped, (std::vector<PointIndex>{4, 6, 100}));
  ASSERT_FALSE (mesh.polygons.empty ());
  EXPECT_EQ (mesh.polygons.size (), stats.w_triangles);
  std::set<pcl::index_t> selected (indices->begin (), indices->end ());
  std::set<std::uint32_t> used;
  const std::vector<Triangle> triangles = trianglesOf (mesh.polygons);
  ASSERT_EQ (triangles.size (), mesh.polygons.size ());
  for (const auto& t : triangles)
    for (auto v : t)
    {
      ASSERT_TRUE (selected.count (v)) << "polygon uses an unselected point";
      ASSERT_TRUE (std::isfinite ((*cloud)[v].x)) << "polygon uses a NaN point";
      used.insert (v);
    }
  EXPECT_EQ (used.size (), indices->size () - 3); // a sphere: every finite selected point on W
  EXPECT_TRUE (describeSurface (triangles).closed_manifold);

  // The timings include the mesh stage and add up to the total.
  double sum = 0.0;
  for (const auto& t : stats.timings)
    sum += t.seconds;
  EXPECT_EQ (stats.timings.back ().stage, "mesh");
  EXPECT_NEAR (sum, stats.total_seconds, 1e-9);

  // Through PCL's PLY writer and reader.
  const std::string path = ::testing::TempDir () + "pcl_wrap_mesh.ply";
  ASSERT_EQ (pcl::io::savePLYFile (path, mesh), 0);
  pcl::PolygonMesh back;
  ASSERT_GE (pcl::io::loadPLYFile (path, back), 0);
  std::remove (path.c_str ());
  ASSERT_EQ (back.polygons.size (), mesh.polygons.size ());
  for (std::size_t i = 0; i < mesh.polygons.size (); ++i)
    EXPECT_EQ (back.polygons[i].vertices, mesh.polygons[i].vertices);
  EXPECT_EQ (std::size_t (back.cloud.width) * back.cloud.height, cloud->size ());
}

TEST (PclWrap, PointsAndPolygonsOverloadAndOtherPointTypes)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGB>> ();
  for (const auto& p : sphereSample (300, 2, 1e-3))
  {
    pcl::PointXYZRGB q;
    q.x = float (p[0]), q.y = float (p[1]), q.z = float (p[2]);
    cloud->push_back (q);
  }
  Wrap<pcl::PointXYZRGB> wrap;
  wrap.setInputCloud (cloud);
  pcl::PointCloud<pcl::PointXYZRGB> points;
  std::vector<pcl::Vertices> polygons;
  wrap.reconstruct (points, polygons);
  EXPECT_EQ (points.size (), cloud->size ());
  EXPECT_EQ (polygons.size (), wrap.getStatistics ().w_triangles);
  EXPECT_EQ (polygons.size (), 2 * cloud->size () - 4); // closed genus-0 triangulation
}

TEST (PclWrap, WeightsFromAVectorOrAPointField)
{
  // Four heavy corners hide the light centre; the rest is a weighted random cloud.
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZI>> ();
  std::vector<Point3> points;
  std::vector<double> weights;
  const auto add = [&] (float x, float y, float z, float w) {
    pcl::PointXYZI p;
    p.x = x, p.y = y, p.z = z, p.intensity = w;
    cloud->push_back (p);
    points.push_back ({x, y, z});
    weights.push_back (w);
  };
  add (1, 1, 1, 10), add (1, -1, -1, 10), add (-1, 1, -1, 10), add (-1, -1, 1, 10), add (0, 0, 0, 0);
  for (const auto& p : cubeSample (300, 4))
    add (float (5 + p[0]), float (p[1]), float (p[2]), float (0.05 * (p[0] + 1)));
  const WrapResult expected = computeWrap (points, weights);
  ASSERT_EQ (expected.hidden.front (), 4u);

  Wrap<pcl::PointXYZI> by_field;
  by_field.setInputCloud (cloud);
  by_field.setWeightField ("intensity");
  pcl::PolygonMesh mesh;
  by_field.reconstruct (mesh);
  EXPECT_EQ (by_field.getResult ().hidden, expected.hidden);
  EXPECT_EQ (by_field.getResult ().surface.triangles, expected.surface.triangles);
  EXPECT_EQ (mesh.polygons.size (), expected.surface.triangles.size ());

  Wrap<pcl::PointXYZI> by_vector;
  by_vector.setInputCloud (cloud);
  by_vector.setWeights (weights);
  by_vector.reconstruct (mesh);
  EXPECT_EQ (by_vector.getResult ().surface.triangles, expected.surface.triangles);

  // Misuse: a clear error (PCL_ERROR) and an empty mesh, never a silent unweighted answer.
  const auto fails = [&] (const std::function<void (Wrap<pcl::PointXYZI>&)>& configure) {
    Wrap<pcl::PointXYZI> wrap;
    wrap.setInputCloud (cloud);
    configure (wrap);
    pcl::PolygonMesh m;
    wrap.reconstruct (m);
    return m.polygons.empty () && wrap.getStatistics ().points_input == 0;
  };
  EXPECT_TRUE (fails ([] (auto& w) { w.setWeights ({1.0, 2.0}); }));
  EXPECT_TRUE (fails ([] (auto& w) { w.setWeightField ("curvature"); }));
  // A non-finite weight skips its point (reported), as a non-finite coordinate does.
  auto nan_weights = weights;
  nan_weights[7] = std::numeric_limits<double>::quiet_NaN ();
  Wrap<pcl::PointXYZI> skipping;
  skipping.setInputCloud (cloud);
  skipping.setWeights (nan_weights);
  skipping.reconstruct (mesh);
  EXPECT_EQ (skipping.getResult ().skipped, std::vector<PointIndex> ({7}));
  EXPECT_FALSE (mesh.polygons.empty ());
  for (const auto& polygon : mesh.polygons)
    for (const auto v : polygon.vertices)
      EXPECT_NE (v, 7u);
}

/** The mesh's cloud is the input: colours, normals and every other field reach the mesh. */
TEST (PclWrap, TheMeshKeepsEveryFieldOfThePoints)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBNormal>> ();
  for (const auto& p : sphereSample (500, 3))
  {
    pcl::PointXYZRGBNormal q;
    q.x = float (p[0]), q.y = float (p[1]), q.z = float (p[2]);
    q.r = std::uint8_t (cloud->size () % 256), q.g = 7, q.b = 9;
    q.normal_x = q.x, q.normal_y = q.y, q.normal_z = q.z, q.curvature = float (cloud->size ());
    cloud->push_back (q);
  }
  Wrap<pcl::PointXYZRGBNormal> wrap;
  wrap.setInputCloud (cloud);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  ASSERT_EQ (mesh.polygons.size (), 2 * cloud->size () - 4);
  pcl::PointCloud<pcl::PointXYZRGBNormal> back;
  pcl::fromPCLPointCloud2 (mesh.cloud, back);
  ASSERT_EQ (back.size (), cloud->size ());
  for (std::size_t i = 0; i < back.size (); ++i)
    ASSERT_TRUE (back[i].rgba == (*cloud)[i].rgba && back[i].normal_y == (*cloud)[i].normal_y &&
                 back[i].curvature == (*cloud)[i].curvature)
        << i;
}

/** A depth image (organised, NaN where nothing came back) is a single layer: one open sheet, no
  * point copied, so the mesh's cloud keeps the image's width and height, facing the sensor at the
  * cloud's origin; with the sensor moved behind the wall, the sheet turns to face it. */
TEST (PclWrap, DepthImageKeepsItsLayoutAndFacesTheSensor)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (80, 60);
  for (std::uint32_t r = 0; r < cloud->height; ++r)
    for (std::uint32_t c = 0; c < cloud->width; ++c)
    {
      const float x = (float (c) - 40.f) / 60.f, y = (float (r) - 30.f) / 60.f, depth = 1.5f + 0.05f * std::sin (5 * x);
      const bool seen = (r * 5 + c * 3) % 13 != 0;
      const float nan = std::numeric_limits<float>::quiet_NaN ();
      cloud->at (c, r) = seen ? pcl::PointXYZ (x * depth, y * depth, depth) : pcl::PointXYZ (nan, nan, nan);
    }
  cloud->is_dense = false;
  const auto facing = [&] (const pcl::PolygonMesh& mesh, const Eigen::Vector3f& sensor) {
    double sum = 0;
    for (const auto& polygon : mesh.polygons)
    {
      const Eigen::Vector3f a = (*cloud)[polygon.vertices[0]].getVector3fMap (),
                            b = (*cloud)[polygon.vertices[1]].getVector3fMap (),
                            c = (*cloud)[polygon.vertices[2]].getVector3fMap ();
      sum += (b - a).cross (c - a).dot (sensor - a);
    }
    return sum;
  };
  Wrap<pcl::PointXYZ> wrap;
  wrap.setInputCloud (cloud);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  EXPECT_TRUE (wrap.getResult ().statistics.single_layer);
  EXPECT_TRUE (wrap.getResult ().copies.empty ());
  EXPECT_EQ (mesh.cloud.width, cloud->width);
  EXPECT_EQ (mesh.cloud.height, cloud->height);
  const OpenSurfaceReport s = describeOpenSurface (trianglesOf (mesh.polygons));
  EXPECT_TRUE (s.manifold);
  EXPECT_TRUE (s.consistently_oriented);
  EXPECT_EQ (s.components, 1u);
  EXPECT_GT (facing (mesh, Eigen::Vector3f::Zero ()), 0.0);

  cloud->sensor_origin_ = Eigen::Vector4f (0.f, 0.f, 5.f, 0.f);
  pcl::PolygonMesh behind;
  wrap.setInputCloud (cloud);
  wrap.reconstruct (behind);
  EXPECT_GT (facing (behind, Eigen::Vector3f (0.f, 0.f, 5.f)), 0.0);
  EXPECT_LT (facing (behind, Eigen::Vector3f::Zero ()), 0.0);
}

/** The manifold option and a region through the PCL class: copies of split points follow the
  * input cloud in the output cloud (an organised cloud then becomes one row), with their fields,
  * and the polygons form a closed 2-manifold; with indices, copies still follow the whole cloud. */
TEST (PclWrap, PointsLeftOffIndexTheCloud)
{
  // Points in a cube (many inside the surface) and a far outlier, every third selected, in an
  // order that is not the cloud's.
  auto sample = cubeSample (3000, 4);
  sample[2700] = {50.0, 50.0, 50.0};
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (const auto& p : sample)
    cloud->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  auto indices = pcl::make_shared<pcl::Indices> ();
  for (int i = int (cloud->size ()) - 3; i >= 0; i -= 3)
    indices->push_back (i);

  Wrap<pcl::PointXYZ> wrap;
  wrap.setInputCloud (cloud);
  wrap.setIndices (indices);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  const WrapResult& r = wrap.getResult ();
  EXPECT_EQ (r.apart, std::vector<PointIndex>{2700});
  EXPECT_TRUE (std::is_sorted (r.off_surface.begin (), r.off_surface.end ()));
  std::set<std::uint32_t> on;
  for (const auto& t : trianglesOf (mesh.polygons))
    on.insert (t.begin (), t.end ());
  ASSERT_GT (r.off_surface.size (), indices->size () / 4) << "a volume: many points inside";
  // The selected points, each on the mesh or off it, and no other.
  std::set<std::uint32_t> all = on;
  for (PointIndex p : r.off_surface)
    EXPECT_TRUE (all.insert (p).second) << "point " << p << " both on and off the mesh";
  EXPECT_EQ (all, std::set<std::uint32_t> (indices->begin (), indices->end ()));
}

TEST (PclWrap, ManifoldCopiesFollowTheInputCloud)
{
  const auto sample = torusSample (200, 1); // sealed: pinch edges
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGB>> (20, 11);
  for (std::size_t i = 0; i < cloud->size (); ++i)
  {
    auto& q = (*cloud)[i];
    q.x = i < sample.size () ? float (sample[i][0]) : std::numeric_limits<float>::quiet_NaN ();
    q.y = i < sample.size () ? float (sample[i][1]) : 0.f;
    q.z = i < sample.size () ? float (sample[i][2]) : 0.f;
    q.r = std::uint8_t (i), q.g = std::uint8_t (i / 256);
  }
  cloud->is_dense = false;
  auto indices = pcl::make_shared<pcl::Indices> ();
  for (int i = 0; i < int (cloud->size ()); ++i)
    if (i != 3)
      indices->push_back (i);

  Wrap<pcl::PointXYZRGB> wrap;
  wrap.setInputCloud (cloud);
  wrap.setIndices (indices);
  wrap.setOutput (Output::raw);
  wrap.setManifold (true);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  const WrapResult& r = wrap.getResult ();
  ASSERT_FALSE (r.copies.empty ());
  EXPECT_GT (r.statistics.pinch_edges_split, 0u);
  pcl::PointCloud<pcl::PointXYZRGB> out;
  pcl::fromPCLPointCloud2 (mesh.cloud, out);
  ASSERT_EQ (out.size (), cloud->size () + r.copies.size ());
  EXPECT_EQ (out.height, 1u);
  for (std::size_t k = 0; k < r.copies.size (); ++k)
  {
    ASSERT_NE (r.copies[k], 3u) << "an unselected point was copied";
    const auto &copy = out[cloud->size () + k], &original = (*cloud)[r.copies[k]];
    EXPECT_EQ (copy.x, original.x);
    EXPECT_EQ (copy.r, original.r);
    EXPECT_EQ (copy.g, original.g);
  }
  const std::vector<Triangle> triangles = trianglesOf (mesh.polygons);
  for (const auto& t : triangles)
    for (auto v : t)
      ASSERT_LT (std::size_t (v), out.size ());
  const SurfaceReport s = describeSurface (triangles);
  EXPECT_TRUE (s.closed_manifold);
  EXPECT_TRUE (s.consistently_oriented);

  // The points-and-polygons overload appends the same copies.
  pcl::PointCloud<pcl::PointXYZRGB> points;
  std::vector<pcl::Vertices> polygons;
  wrap.reconstruct (points, polygons);
  EXPECT_EQ (points.size (), out.size ());
  EXPECT_EQ (polygons.size (), mesh.polygons.size ());

  // A region with front deletion: the torus's hole opens, and W is a manifold without splitting.
  auto torus = pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGB>> ();
  for (const auto& p : torusSample (1000, 2))
  {
    pcl::PointXYZRGB q;
    q.x = float (p[0]), q.y = float (p[1]), q.z = float (p[2]);
    torus->push_back (q);
  }
  Wrap<pcl::PointXYZRGB> local;
  local.setInputCloud (torus);
  local.setDelta (0.2);
  local.setRegion (Region::sphere (0, 0, 0, 0.7));
  pcl::PolygonMesh opened;
  local.reconstruct (opened);
  EXPECT_GT (local.getStatistics ().sinks_deleted, 0u);
  const SurfaceReport o = describeSurface (trianglesOf (opened.polygons));
  EXPECT_TRUE (o.closed_manifold);
  EXPECT_EQ (o.euler, 0);
}

/** The filtration through the PCL class speaks cloud indices, like the mesh. */
TEST (PclWrap, FiltrationSurfacesIndexTheCloud)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (const auto& p : torusSample (1600, 3))
    cloud->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  auto indices = pcl::make_shared<pcl::Indices> ();
  for (int i = 1; i < int (cloud->size ()); i += 2)
    indices->push_back (i);
  Wrap<pcl::PointXYZ> wrap;
  wrap.setInputCloud (cloud);
  wrap.setIndices (indices);
  wrap.setOutput (Output::raw); // the filtration's surfaces are the paper's W
  wrap.setFiltration (true);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  const Filtration& f = wrap.getResult ().filtration;
  ASSERT_FALSE (f.empty ());
  std::set<std::array<std::uint32_t, 3>> from_mesh, basic;
  for (const auto& polygon : mesh.polygons)
    from_mesh.insert ({std::uint32_t (polygon.vertices[0]), std::uint32_t (polygon.vertices[1]),
                       std::uint32_t (polygon.vertices[2])});
  for (const auto& t : f.surface (std::numeric_limits<double>::infinity ()).triangles)
    basic.insert ({t[0], t[1], t[2]});
  EXPECT_EQ (basic, from_mesh);
  const std::set<pcl::index_t> selected (indices->begin (), indices->end ());
  const WrapSurface tighter = f.surface (f.sinkSizes ().at (3));
  ASSERT_FALSE (tighter.triangles.empty ());
  for (const auto& t : tighter.triangles)
    for (auto v : t)
      ASSERT_TRUE (selected.count (v));
}

TEST (PclWrap, EmptyCloudGivesEmptyMesh)
{
  Wrap<pcl::PointXYZ> wrap;
  wrap.setInputCloud (pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ());
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  EXPECT_TRUE (mesh.polygons.empty ());
}

} // namespace
} // namespace pcl_wrap::test
