// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "threshold_option.h"

#include <cmath>
#include <cstdlib>

namespace pcl_wrap::apps
{

bool
isThresholdOption (const std::string& arg)
{
  return arg == "--delta" || arg == "--radius" || arg == "--radius-rel" || arg == "--sinks" || arg == "--mode";
}

std::string
applyThresholdOption (const std::string& arg, const std::string& value, WrapParameters& parameters, int& thresholds)
{
  char* end = nullptr;
  if (arg == "--mode")
  {
    if (value != "front" && value != "global")
      return "--mode takes front or global";
    parameters.deletion = value == "front" ? SinkDeletion::front : SinkDeletion::global;
    return "";
  }
  if (arg == "--sinks")
  {
    const long long j = std::strtoll (value.c_str (), &end, 10);
    if (value.empty () || *end != '\0' || j < 1)
      return "--sinks takes a whole number >= 1";
    parameters.threshold = Threshold::largest (static_cast<std::size_t> (j));
  }
  else
  {
    const double x = std::strtod (value.c_str (), &end);
    if (value.empty () || *end != '\0' || !std::isfinite (x) || (arg != "--delta" && x <= 0))
      return arg + " takes a finite number" + (arg == "--delta" ? "" : " > 0");
    parameters.threshold = arg == "--radius-rel" ? Threshold::relativeRadius (x)
                           : arg == "--radius"   ? Threshold::radius (x)
                                                 : Threshold::size (x);
  }
  if (++thresholds > 1)
    return "--delta, --radius, --radius-rel and --sinks each set the threshold: give one";
  return "";
}

} // namespace pcl_wrap::apps
