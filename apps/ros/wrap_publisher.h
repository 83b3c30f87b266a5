// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/wrap_parameters.h>

#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>

#include <string>
#include <vector>

namespace pcl_wrap_ros
{

/** \brief Reads the wrap's parameters from \a private_nh (one of ~delta, ~radius, ~radius_rel and
  * ~sinks; ~mode, ~region, ~output, ~manifold, ~viewpoint, ~threads, ~weight_scale), each
  * defaulting to pcl_wrap::WrapParameters' own default. The node reads ~weight_field itself.
  * \throws std::invalid_argument naming the parameter when a value has the wrong type or no
  *         meaning */
pcl_wrap::WrapParameters
readParameters (const ros::NodeHandle& private_nh);

/** \brief ~weight_field: the points' field holding the weights (empty: none).
  * \throws std::invalid_argument when it is not a string */
std::string
readWeightField (const ros::NodeHandle& private_nh);

/** \brief The parameters under \a private_nh that the node does not know (a typo, most likely). */
std::vector<std::string>
unknownParameters (const ros::NodeHandle& private_nh);

/** \brief The node's work, shared by the node and the nodelet: subscribes to "cloud"
  * (sensor_msgs/PointCloud2), wraps each cloud and publishes "mesh" (pcl_msgs/PolygonMesh; its
  * cloud is the input cloud with all its fields, followed by the copies of a split) and "marker"
  * (visualization_msgs/Marker, a TRIANGLE_LIST for RViz, in the input's colours when it has an
  * rgb or rgba field), both latched and with the input's header; logs a line per cloud. */
class WrapPublisher
{
public:
  WrapPublisher (ros::NodeHandle nh, const ros::NodeHandle& private_nh);

private:
  void onCloud (const sensor_msgs::PointCloud2::ConstPtr& msg);

  pcl_wrap::WrapParameters parameters_;
  std::string weight_field_; ///< the points' field holding the weights; empty: none
  ros::Publisher mesh_publisher_;
  ros::Publisher marker_publisher_;
  ros::Subscriber subscriber_;
};

} // namespace pcl_wrap_ros
