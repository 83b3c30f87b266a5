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
  // Held for the whole run: were the publisher's handles the only ones, an error would shut the
  // node down, and its logging with it, before the error is logged.
  ros::NodeHandle nh, private_nh ("~");
  try
  {
    pcl_wrap_ros::WrapPublisher publisher (nh, private_nh);
    ros::spin ();
  }
  catch (const std::exception& e)
  {
    ROS_FATAL_STREAM ("pcl_wrap: " << e.what () << " (the node's parameters are under " << private_nh.getNamespace ()
                                   << "; rosparam delete removes a stale one)");
    ros::console::shutdown ();
    return 1;
  }
  return 0;
}
