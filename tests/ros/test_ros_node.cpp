// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The ROS node against a real ROS master (started by run_ros_test.sh): a real cloud in, the mesh
// and the marker out, compared with the library on the same cloud. Three nodes run: /basic with
// the defaults (started through the launch file), /launched with the launch file's arguments
// output:=raw radius_rel:=2 manifold:=true, and the nodelet /tight with these as parameters.
#include "point_file.h"

#include <pcl_wrap/wrap.h>

#include <pcl/PolygonMesh.h>
#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <pcl_msgs/PolygonMesh.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/Marker.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

namespace
{

std::string data_file;

/** Publishes \a cloud on NS/cloud and waits for NS/mesh and NS/marker. */
struct Exchange
{
  ros::Time stamp; ///< the cloud's: the outputs are latched, so older ones come first
  pcl_msgs::PolygonMesh::ConstPtr mesh;
  visualization_msgs::Marker::ConstPtr marker;
};

template <class Point>
Exchange
exchange (const std::string& ns, const pcl::PointCloud<Point>& cloud, const std::string& frame)
{
  ros::NodeHandle nh (ns);
  static std::uint32_t exchanges = 0;
  Exchange got;
  got.stamp = ros::Time (1234, 5678 + exchanges++);
  auto mesh_sub = nh.subscribe<pcl_msgs::PolygonMesh> ("mesh", 1, [&] (const pcl_msgs::PolygonMesh::ConstPtr& m) {
    if (m->header.stamp == got.stamp)
      got.mesh = m;
  });
  auto marker_sub =
      nh.subscribe<visualization_msgs::Marker> ("marker", 1, [&] (const visualization_msgs::Marker::ConstPtr& m) {
        if (m->header.stamp == got.stamp)
          got.marker = m;
      });
  auto publisher = nh.advertise<sensor_msgs::PointCloud2> ("cloud", 1);
  const ros::WallTime deadline = ros::WallTime::now () + ros::WallDuration (120.0);
  while ((publisher.getNumSubscribers () == 0 || mesh_sub.getNumPublishers () == 0 ||
          marker_sub.getNumPublishers () == 0) &&
         ros::WallTime::now () < deadline)
  {
    ros::spinOnce ();
    ros::WallDuration (0.05).sleep ();
  }
  sensor_msgs::PointCloud2 msg;
  pcl::toROSMsg (cloud, msg);
  msg.header.frame_id = frame;
  msg.header.stamp = got.stamp;
  msg.header.seq = 7;
  publisher.publish (msg);
  while ((!got.mesh || !got.marker) && ros::WallTime::now () < deadline)
  {
    ros::spinOnce ();
    ros::WallDuration (0.01).sleep ();
  }
  return got;
}

/** What the library gives on the same cloud with the same parameters. */
pcl::PolygonMesh
libraryMesh (const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud, const pcl_wrap::WrapParameters& parameters)
{
  pcl_wrap::Wrap<pcl::PointXYZ> wrap;
  wrap.setParameters (parameters);
  wrap.setInputCloud (cloud);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  return mesh;
}

void
expectSameAsLibrary (const Exchange& got, const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud,
                     const pcl_wrap::WrapParameters& parameters, const std::string& frame)
{
  ASSERT_TRUE (got.mesh) << "no mesh received";
  ASSERT_TRUE (got.marker) << "no marker received";
  const pcl::PolygonMesh expected = libraryMesh (cloud, parameters);
  ASSERT_FALSE (expected.polygons.empty ());
  EXPECT_EQ (got.mesh->polygons.size (), expected.polygons.size ());
  EXPECT_EQ (got.mesh->header.frame_id, frame);
  EXPECT_EQ (got.mesh->header.stamp, got.stamp);
  EXPECT_EQ (got.mesh->cloud.header.frame_id, frame);
  EXPECT_EQ (got.marker->header.frame_id, frame);
  EXPECT_EQ (got.marker->type, visualization_msgs::Marker::TRIANGLE_LIST);
  EXPECT_EQ (got.marker->points.size (), 3 * got.mesh->polygons.size ());

  pcl::PolygonMesh mesh;
  pcl_conversions::toPCL (*got.mesh, mesh);
  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::fromPCLPointCloud2 (mesh.cloud, points);
  EXPECT_EQ (points.size (), std::size_t (expected.cloud.width) * expected.cloud.height);
  EXPECT_GE (points.size (), cloud->size ());
  for (std::size_t i = 0; i < mesh.polygons.size (); ++i)
  {
    ASSERT_EQ (mesh.polygons[i].vertices, expected.polygons[i].vertices);
    for (const auto v : mesh.polygons[i].vertices)
    {
      ASSERT_LT (std::size_t (v), points.size ());
      ASSERT_TRUE (std::isfinite (points[v].x)) << "a triangle uses a NaN point";
    }
  }
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
bunny ()
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  for (const auto& p : pcl_wrap::apps::readPointFile (data_file).points)
    cloud->push_back (pcl::PointXYZ (float (p[0]), float (p[1]), float (p[2])));
  return cloud;
}

/** A depth camera's view of a bumpy surface: organised, NaN where nothing was seen. */
pcl::PointCloud<pcl::PointXYZ>::Ptr
depthImage ()
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> (64, 48);
  for (std::uint32_t r = 0; r < cloud->height; ++r)
    for (std::uint32_t c = 0; c < cloud->width; ++c)
    {
      const float x = (float (c) - 32.f) / 32.f, y = (float (r) - 24.f) / 32.f;
      const bool seen = x * x + y * y < 0.8f && (r * 7 + c * 3) % 11 != 0;
      const float nan = std::numeric_limits<float>::quiet_NaN ();
      cloud->at (c, r) = seen ? pcl::PointXYZ (x, y, 2.f + 0.1f * std::sin (4 * x) * std::cos (3 * y))
                              : pcl::PointXYZ (nan, nan, nan);
    }
  cloud->is_dense = false;
  return cloud;
}

pcl_wrap::WrapParameters
tightParameters ()
{
  pcl_wrap::WrapParameters p; // what run_ros_test.sh gives the /tight node
  p.output = pcl_wrap::Output::raw;
  p.threshold = pcl_wrap::Threshold::relativeRadius (2);
  p.manifold = true;
  return p;
}

TEST (RosNode, BunnyThroughTheDefaultNodeMatchesTheLibrary)
{
  const auto cloud = bunny ();
  expectSameAsLibrary (exchange ("basic", *cloud, "bunny_frame"), cloud, pcl_wrap::WrapParameters (), "bunny_frame");
}

TEST (RosNode, OrganisedCloudWithNans)
{
  const auto cloud = depthImage ();
  const Exchange got = exchange ("basic", *cloud, "camera");
  expectSameAsLibrary (got, cloud, pcl_wrap::WrapParameters (), "camera");
  ASSERT_TRUE (got.mesh);
  // A depth image is a single layer: one open sheet, no point copied, the cloud organised as it
  // came, the sheet facing the camera at the frame's origin.
  EXPECT_EQ (got.mesh->cloud.width, cloud->width);
  EXPECT_EQ (got.mesh->cloud.height, cloud->height);
  ASSERT_FALSE (got.mesh->polygons.empty ());
  double towards_camera = 0;
  for (const auto& polygon : got.mesh->polygons)
  {
    const auto &a = (*cloud)[polygon.vertices[0]], &b = (*cloud)[polygon.vertices[1]],
               &c = (*cloud)[polygon.vertices[2]];
    const Eigen::Vector3f n =
        (b.getVector3fMap () - a.getVector3fMap ()).cross (c.getVector3fMap () - a.getVector3fMap ());
    towards_camera += -n.dot (a.getVector3fMap ());
    for (const auto v : polygon.vertices)
      EXPECT_TRUE (std::isfinite ((*cloud)[v].z)) << "a polygon on a point nothing was seen at";
  }
  EXPECT_GT (towards_camera, 0.0);
  pcl_wrap::WrapParameters raw;
  raw.output = pcl_wrap::Output::raw;
  EXPECT_EQ (libraryMesh (cloud, raw).cloud.height, cloud->height) << "the raw W keeps an organised cloud organised";
}

TEST (RosNode, ParametersReachTheNodeAndTheNodelet)
{
  const auto cloud = bunny ();
  pcl_wrap::WrapParameters raw;
  raw.output = pcl_wrap::Output::raw;
  const pcl::PolygonMesh basic = libraryMesh (cloud, raw);
  for (const std::string ns : {"tight", "launched"})
  {
    SCOPED_TRACE (ns);
    const Exchange got = exchange (ns, *cloud, "bunny_frame");
    expectSameAsLibrary (got, cloud, tightParameters (), "bunny_frame");
    ASSERT_TRUE (got.mesh);
    EXPECT_NE (got.mesh->polygons.size (), basic.polygons.size ()) << "~radius_rel should change the surface";
  }
}

TEST (RosNode, TheMeshKeepsEveryFieldAndTheMarkerTheColours)
{
  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud;
  const auto source = bunny ();
  for (const auto& p : *source)
  {
    pcl::PointXYZRGBNormal q;
    q.x = p.x, q.y = p.y, q.z = p.z;
    q.r = std::uint8_t (std::lround (255 * std::clamp ((p.y + 0.1f) * 5.f, 0.f, 1.f))), q.g = 40, q.b = 200;
    q.normal_x = 0, q.normal_y = 0, q.normal_z = 1, q.curvature = p.x;
    cloud.push_back (q);
  }
  const Exchange got = exchange ("basic", cloud, "coloured");
  ASSERT_TRUE (got.mesh && got.marker);
  pcl::PointCloud<pcl::PointXYZRGBNormal> back;
  pcl::PolygonMesh mesh;
  pcl_conversions::toPCL (*got.mesh, mesh);
  for (const char* field : {"rgb", "normal_x", "normal_y", "normal_z", "curvature"})
    EXPECT_NE (pcl::getFieldIndex (mesh.cloud, field), -1) << field;
  pcl::fromPCLPointCloud2 (mesh.cloud, back);
  ASSERT_GE (back.size (), cloud.size ()); // then the copies, if any
  for (std::size_t i = 0; i < cloud.size (); ++i)
    ASSERT_TRUE (back[i].rgba == cloud[i].rgba && back[i].curvature == cloud[i].curvature) << i;
  ASSERT_FALSE (mesh.polygons.empty ());
  ASSERT_EQ (got.marker->colors.size (), got.marker->points.size ());
  for (std::size_t k = 0; k < got.marker->colors.size (); ++k)
  {
    const auto& p = cloud[mesh.polygons[k / 3].vertices[k % 3]];
    ASSERT_NEAR (got.marker->colors[k].r, p.r / 255.0, 1e-6);
    ASSERT_NEAR (got.marker->colors[k].b, p.b / 255.0, 1e-6);
  }
}

TEST (RosNode, TheOutputsAreLatched)
{
  const auto cloud = bunny ();
  ASSERT_TRUE (exchange ("basic", *cloud, "first").mesh);
  // A subscriber that comes later (RViz opened afterwards) still gets the last mesh and marker.
  ros::NodeHandle nh ("basic");
  pcl_msgs::PolygonMesh::ConstPtr mesh;
  visualization_msgs::Marker::ConstPtr marker;
  auto mesh_sub = nh.subscribe<pcl_msgs::PolygonMesh> ("mesh", 1, [&] (const auto& m) { mesh = m; });
  auto marker_sub = nh.subscribe<visualization_msgs::Marker> ("marker", 1, [&] (const auto& m) { marker = m; });
  const ros::WallTime deadline = ros::WallTime::now () + ros::WallDuration (30.0);
  while ((!mesh || !marker) && ros::WallTime::now () < deadline)
  {
    ros::spinOnce ();
    ros::WallDuration (0.01).sleep ();
  }
  ASSERT_TRUE (mesh && marker);
  EXPECT_EQ (mesh->header.frame_id, "first");
  EXPECT_EQ (marker->header.frame_id, "first");
}

TEST (RosNode, EveryTopicAdvertisedOnceWithItsType)
{
  ros::master::V_TopicInfo topics;
  ASSERT_TRUE (ros::master::getTopics (topics));
  int meshes = 0, markers = 0;
  for (const auto& t : topics)
  {
    meshes += t.name == "/basic/mesh" && t.datatype == "pcl_msgs/PolygonMesh";
    markers += t.name == "/basic/marker" && t.datatype == "visualization_msgs/Marker";
  }
  EXPECT_EQ (meshes, 1);
  EXPECT_EQ (markers, 1);
}

} // namespace

int
main (int argc, char** argv)
{
  ::testing::InitGoogleTest (&argc, argv);
  ros::init (argc, argv, "pcl_wrap_test", ros::init_options::AnonymousName);
  if (argc < 2)
  {
    std::fprintf (stderr, "usage: test_ros_node POINT_FILE\n");
    return 2;
  }
  data_file = argv[1];
  return RUN_ALL_TESTS ();
}
