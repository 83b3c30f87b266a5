// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// pcl_wrap_node: cloud (sensor_msgs/PointCloud2) in, mesh (pcl_msgs/PolygonMesh) and marker
// (visualization_msgs/Marker) out. Parameters: see readParameters().
#include "wrap_publisher.h"

#include <exception>

int
main (int argc, char** argv)
{
  ros::init (argc, argv, "pcl_wrap");
  try
  {
    pcl_wrap_ros::WrapPublisher publisher (ros::NodeHandle (), ros::NodeHandle ("~"));
    ros::spin ();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM ("pcl_wrap: " << e.what ());
    return 1;
  }
  return 0;
}
