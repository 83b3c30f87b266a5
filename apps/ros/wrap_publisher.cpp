// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap_publisher.h"

#include <pcl_wrap/point_field.h>
#include <pcl_wrap/wrap.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/PolygonMesh.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <pcl_msgs/PolygonMesh.h>
#include <visualization_msgs/Marker.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace pcl_wrap_ros
{

pcl_wrap::WrapParameters
readParameters (const ros::NodeHandle& private_nh)
{
  pcl_wrap::WrapParameters p;
  // One threshold: ~delta, ~radius, ~radius_rel or ~sinks, not two of them.
  int thresholds = 0;
  double value = 0.0;
  if (private_nh.getParam ("delta", value) && ++thresholds)
    p.threshold = pcl_wrap::Threshold::size (value);
  if (private_nh.getParam ("radius", value) && ++thresholds)
    p.threshold = pcl_wrap::Threshold::radius (value);
  if (private_nh.getParam ("radius_rel", value) && ++thresholds)
    p.threshold = pcl_wrap::Threshold::relativeRadius (value);
  std::string mode = p.deletion == pcl_wrap::SinkDeletion::front ? "front" : "global";
  private_nh.param ("mode", mode, mode);
  if (mode != "front" && mode != "global")
    throw std::invalid_argument ("~mode must be front or global, not '" + mode + "'");
  p.deletion = mode == "front" ? pcl_wrap::SinkDeletion::front : pcl_wrap::SinkDeletion::global;
  int sinks = 0;
  if (private_nh.getParam ("sinks", sinks) && ++thresholds)
  {
    if (sinks < 1)
      throw std::invalid_argument ("~sinks must be >= 1");
    p.threshold = pcl_wrap::Threshold::largest (static_cast<std::size_t> (sinks));
  }
  if (thresholds > 1)
    throw std::invalid_argument ("~delta, ~radius, ~radius_rel and ~sinks each set the threshold: give one");
  std::vector<double> region;
  if (private_nh.getParam ("region", region))
  {
    if (region.size () == 4)
      p.region = pcl_wrap::Region::sphere (region[0], region[1], region[2], region[3]);
    else if (region.size () == 6)
      p.region = pcl_wrap::Region::box (region[0], region[1], region[2], region[3], region[4], region[5]);
    else
      throw std::invalid_argument ("~region takes [x, y, z, r] (a sphere) or [x0, y0, z0, x1, y1, z1] (a box)");
  }
  std::string output = p.output == pcl_wrap::Output::raw      ? "raw"
                       : p.output == pcl_wrap::Output::closed ? "closed"
                                                              : "surface";
  private_nh.param ("output", output, output);
  if (output != "surface" && output != "closed" && output != "raw")
    throw std::invalid_argument ("~output must be surface, closed or raw, not '" + output + "'");
  p.output = output == "raw"      ? pcl_wrap::Output::raw
             : output == "closed" ? pcl_wrap::Output::closed
                                  : pcl_wrap::Output::surface;
  private_nh.param ("manifold", p.manifold, p.manifold);
  std::vector<double> viewpoint;
  if (private_nh.getParam ("viewpoint", viewpoint))
  {
    if (viewpoint.size () != 3)
      throw std::invalid_argument ("~viewpoint takes [x, y, z]: where an open sheet faces");
    p.viewpoint = std::array<double, 3>{viewpoint[0], viewpoint[1], viewpoint[2]};
  }
  int threads = static_cast<int> (p.num_threads);
  private_nh.param ("threads", threads, threads);
  p.num_threads = static_cast<unsigned> (std::max (threads, 0));
  private_nh.param ("weight_scale", p.weight_scale, p.weight_scale);
  p.keep_complex = false; // the node publishes W only
  return p;
}

WrapPublisher::WrapPublisher (ros::NodeHandle nh, const ros::NodeHandle& private_nh)
  : parameters_ (readParameters (private_nh)), weight_field_ (private_nh.param<std::string> ("weight_field", ""))
  , mesh_publisher_ (nh.advertise<pcl_msgs::PolygonMesh> ("mesh", 1))
  , marker_publisher_ (nh.advertise<visualization_msgs::Marker> ("marker", 1))
  , subscriber_ (nh.subscribe ("cloud", 1, &WrapPublisher::onCloud, this))
{}

namespace
{

visualization_msgs::Marker
triangleList (const pcl::PointCloud<pcl::PointXYZ>& points, const std::vector<pcl::Vertices>& polygons)
{
  visualization_msgs::Marker m;
  m.ns = "pcl_wrap";
  m.id = 0;
  m.type = visualization_msgs::Marker::TRIANGLE_LIST;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color.r = 0.8f, m.color.g = 0.7f, m.color.b = 0.5f, m.color.a = 1.0f;
  m.points.reserve (3 * polygons.size ());
  for (const auto& polygon : polygons)
    for (const auto v : polygon.vertices)
    {
      geometry_msgs::Point q;
      q.x = points[v].x, q.y = points[v].y, q.z = points[v].z;
      m.points.push_back (q);
    }
  return m;
}

} // namespace

void
WrapPublisher::onCloud (const sensor_msgs::PointCloud2::ConstPtr& msg)
{
  pcl::PCLPointCloud2 input;
  pcl_conversions::toPCL (*msg, input);
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  pcl::fromPCLPointCloud2 (input, *cloud);

  pcl_wrap::Wrap<pcl::PointXYZ> wrap;
  wrap.setParameters (parameters_);
  wrap.setWeightField ("");
  try
  {
    // Checked against the message's own layout: a malformed message is an error, not a crash.
    wrap.setWeights (weight_field_.empty () ? std::vector<double> ()
                                            : pcl_wrap::readFieldValues (input, weight_field_));
  }
  catch (const std::exception& e)
  {
    ROS_ERROR_STREAM ("pcl_wrap: " << e.what () << "; cloud skipped");
    return;
  }
  wrap.setInputCloud (cloud);
  pcl::PolygonMesh mesh;
  wrap.reconstruct (mesh);
  const auto& stats = wrap.getStatistics ();
  ROS_DEBUG_STREAM ("pcl_wrap: " << stats.points_used << " points, " << mesh.polygons.size () << " triangles in "
                                 << stats.total_seconds << " s");

  // moveFromPCL would drop the polygons; fromPCL copies them.
  pcl_msgs::PolygonMesh out;
  pcl_conversions::fromPCL (mesh, out);
  out.header = msg->header;
  out.cloud.header = msg->header;
  mesh_publisher_.publish (out);

  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::fromPCLPointCloud2 (mesh.cloud, points);
  visualization_msgs::Marker marker = triangleList (points, mesh.polygons);
  marker.header = msg->header;
  marker_publisher_.publish (marker);
}

} // namespace pcl_wrap_ros
