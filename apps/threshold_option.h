// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/wrap_parameters.h>

#include <string>

namespace pcl_wrap::apps
{

/** \brief Is \a arg one of the options that set how tight the wrap is: --delta, --radius,
  * --radius-rel, --sinks (a threshold each) or --mode? */
bool
isThresholdOption (const std::string& arg);

/** \brief Sets the threshold or deletion mode that option \a arg with \a value gives in
  * \a parameters, counting the thresholds given so far in \a thresholds; returns the usage error
  * if \a value is not one it takes or a second threshold is given, else "". */
std::string
applyThresholdOption (const std::string& arg, const std::string& value, WrapParameters& parameters, int& thresholds);

} // namespace pcl_wrap::apps
