// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The node as a nodelet (pcl_wrap/WrapNodelet), for zero-copy pipelines in a nodelet manager.
#include "wrap_publisher.h"

#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include <exception>
#include <memory>

namespace pcl_wrap_ros
{

class WrapNodelet : public nodelet::Nodelet
{
  void onInit () override
  {
    try
    {
      publisher_ = std::make_unique<WrapPublisher> (getNodeHandle (), getPrivateNodeHandle ());
    }
    catch (const std::exception& e) // the manager runs on: this nodelet stays idle, and says why
    {
      NODELET_FATAL_STREAM ("pcl_wrap: " << e.what () << "; this nodelet does not subscribe");
    }
  }

  std::unique_ptr<WrapPublisher> publisher_;
};

} // namespace pcl_wrap_ros

PLUGINLIB_EXPORT_CLASS (pcl_wrap_ros::WrapNodelet, nodelet::Nodelet)
