// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap_publisher.h"

#include <pcl_wrap/cloud_copies.h>
#include <pcl_wrap/point_field.h>
#include <pcl_wrap/wrap.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/PolygonMesh.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <pcl_msgs/PolygonMesh.h>
#include <visualization_msgs/Marker.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace pcl_wrap_ros
{

namespace
{

/** ~name into \a value when it is set; a value of another type is an error, not the default. */
template <class T>
bool
get (const ros::NodeHandle& nh, const std::string& name, T& value, const std::string& expected)
{
  if (!nh.hasParam (name))
    return false;
  if (!nh.getParam (name, value))
    throw std::invalid_argument ("~" + name + " must be " + expected);
  return true;
}

const std::vector<std::string> PARAMETERS = {"delta",     "radius",  "radius_rel",   "sinks",
                                             "mode",      "region",  "output",       "manifold",
                                             "viewpoint", "threads", "weight_scale", "weight_field"};

} // namespace

pcl_wrap::WrapParameters
readParameters (const ros::NodeHandle& private_nh)
{
  pcl_wrap::WrapParameters p;
  // One threshold: ~delta, ~radius, ~radius_rel or ~sinks, not two of them.
  int thresholds = 0;
  double value = 0.0;
  if (get (private_nh, "delta", value, "a number") && ++thresholds)
    p.threshold = pcl_wrap::Threshold::size (value);
  for (const char* name : {"radius", "radius_rel"})
    if (get (private_nh, name, value, "a number > 0") && ++thresholds)
    {
      if (!(value > 0 && std::isfinite (value)))
        throw std::invalid_argument (std::string ("~") + name + " must be a number > 0");
      p.threshold = name == std::string ("radius") ? pcl_wrap::Threshold::radius (value)
                                                   : pcl_wrap::Threshold::relativeRadius (value);
    }
  int sinks = 0;
  if (get (private_nh, "sinks", sinks, "a whole number >= 1") && ++thresholds)
  {
    if (sinks < 1)
      throw std::invalid_argument ("~sinks must be a whole number >= 1");
    p.threshold = pcl_wrap::Threshold::largest (static_cast<std::size_t> (sinks));
  }
  if (thresholds > 1)
    throw std::invalid_argument ("~delta, ~radius, ~radius_rel and ~sinks each set the threshold: give one");
  std::string mode = "front";
  get (private_nh, "mode", mode, "front or global");
  if (mode != "front" && mode != "global")
    throw std::invalid_argument ("~mode must be front or global, not '" + mode + "'");
  p.deletion = mode == "front" ? pcl_wrap::SinkDeletion::front : pcl_wrap::SinkDeletion::global;
  std::vector<double> region;
  if (get (private_nh, "region", region, "a list of numbers"))
  {
    if (region.size () == 4)
      p.region = pcl_wrap::Region::sphere (region[0], region[1], region[2], region[3]);
    else if (region.size () == 6)
      p.region = pcl_wrap::Region::box (region[0], region[1], region[2], region[3], region[4], region[5]);
    else
      throw std::invalid_argument ("~region takes [x, y, z, r] (a sphere) or [x0, y0, z0, x1, y1, z1] (a box)");
  }
  std::string output = "surface";
  get (private_nh, "output", output, "surface, closed or raw");
  if (output != "surface" && output != "closed" && output != "raw")
    throw std::invalid_argument ("~output must be surface, closed or raw, not '" + output + "'");
  p.output = output == "raw"      ? pcl_wrap::Output::raw
             : output == "closed" ? pcl_wrap::Output::closed
                                  : pcl_wrap::Output::surface;
  get (private_nh, "manifold", p.manifold, "true or false");
  if (p.manifold && p.output != pcl_wrap::Output::raw)
    throw std::invalid_argument (
        "~manifold splits the raw W (~output raw); the default surface is a 2-manifold already");
  std::vector<double> viewpoint;
  if (get (private_nh, "viewpoint", viewpoint, "a list of three numbers"))
  {
    if (viewpoint.size () != 3)
      throw std::invalid_argument ("~viewpoint takes [x, y, z]: where an open sheet faces");
    p.viewpoint = std::array<double, 3>{viewpoint[0], viewpoint[1], viewpoint[2]};
  }
  int threads = 0;
  get (private_nh, "threads", threads, "a whole number (0: all cores)");
  if (threads < 0 || threads > 4096)
    throw std::invalid_argument ("~threads must be a whole number from 0 (all cores) to 4096");
  p.num_threads = static_cast<unsigned> (threads);
  get (private_nh, "weight_scale", p.weight_scale, "a number");
  p.keep_complex = false;        // the node publishes the surface only
  pcl_wrap::checkParameters (p); // what depends on several: a region needs a size threshold, ...
  return p;
}

std::vector<std::string>
unknownParameters (const ros::NodeHandle& private_nh)
{
  std::vector<std::string> names, unknown;
  ros::param::getParamNames (names);
  const std::string prefix = private_nh.getNamespace () + "/";
  for (const std::string& name : names)
    if (name.rfind (prefix, 0) == 0 &&
        std::find (PARAMETERS.begin (), PARAMETERS.end (), name.substr (prefix.size ())) == PARAMETERS.end ())
      unknown.push_back (name);
  return unknown;
}

std::string
readWeightField (const ros::NodeHandle& private_nh)
{
  std::string field;
  get (private_nh, "weight_field", field, "a field name");
  return field;
}

WrapPublisher::WrapPublisher (ros::NodeHandle nh, const ros::NodeHandle& private_nh)
  : parameters_ (readParameters (private_nh)),
    weight_field_ (readWeightField (private_nh)),
    mesh_publisher_ (nh.advertise<pcl_msgs::PolygonMesh> ("mesh", 1, true)) // latched: RViz opened later sees it
    ,
    marker_publisher_ (nh.advertise<visualization_msgs::Marker> ("marker", 1, true)),
    subscriber_ (nh.subscribe ("cloud", 1, &WrapPublisher::onCloud, this))
{
  for (const std::string& name : unknownParameters (private_nh))
    ROS_WARN_STREAM ("pcl_wrap: unknown parameter " << name << " ignored");
  ROS_INFO_STREAM ("pcl_wrap: wrapping " << subscriber_.getTopic () << " into " << mesh_publisher_.getTopic ()
                                         << " and " << marker_publisher_.getTopic ());
}

namespace
{

visualization_msgs::Marker
triangleList (const pcl::PointCloud<pcl::PointXYZ>& points, const std::vector<pcl::Vertices>& polygons,
              const std::vector<std::array<std::uint8_t, 4>>& colours)
{
  visualization_msgs::Marker m;
  m.ns = "pcl_wrap";
  m.id = 0;
  m.type = visualization_msgs::Marker::TRIANGLE_LIST;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = m.scale.y = m.scale.z = 1.0;
  m.color.r = 0.8f, m.color.g = 0.7f, m.color.b = 0.5f, m.color.a = 1.0f; // without colours of its own
  m.points.reserve (3 * polygons.size ());
  for (const auto& polygon : polygons)
    for (const auto v : polygon.vertices)
    {
      geometry_msgs::Point q;
      q.x = points[v].x, q.y = points[v].y, q.z = points[v].z;
      m.points.push_back (q);
      if (v < colours.size ())
      {
        std_msgs::ColorRGBA c;
        c.r = colours[v][0] / 255.f, c.g = colours[v][1] / 255.f, c.b = colours[v][2] / 255.f,
        c.a = colours[v][3] / 255.f;
        m.colors.push_back (c);
      }
    }
  if (m.colors.size () != m.points.size ())
    m.colors.clear ();
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
  ROS_INFO_STREAM ("pcl_wrap: " << msg->width * msg->height << " points (" << stats.points_used << " used, "
                                << stats.points_off_surface << " off the surface) -> " << mesh.polygons.size ()
                                << " triangles in " << stats.total_seconds << " s");

  // The mesh's vertices are the input's points with every field they have, then the copies.
  const std::vector<pcl_wrap::PointIndex>& copies = wrap.getResult ().copies;
  mesh.cloud = input;
  pcl_wrap::appendCopies (mesh.cloud, copies);
  // moveFromPCL would drop the polygons; fromPCL copies them.
  pcl_msgs::PolygonMesh out;
  pcl_conversions::fromPCL (mesh, out);
  out.header = msg->header;
  out.cloud.header = msg->header;
  mesh_publisher_.publish (out);

  for (const pcl_wrap::PointIndex c : copies)
    cloud->push_back ((*cloud)[c]);
  std::vector<std::array<std::uint8_t, 4>> colours; // of the mesh's vertices, copies included
  try
  {
    colours = pcl_wrap::readColours (mesh.cloud).rgba;
  }
  catch (const std::invalid_argument&) // a malformed colour field: the marker's own colour
  {}
  visualization_msgs::Marker marker = triangleList (*cloud, mesh.polygons, colours);
  marker.header = msg->header;
  marker_publisher_.publish (marker);
}

} // namespace pcl_wrap_ros
