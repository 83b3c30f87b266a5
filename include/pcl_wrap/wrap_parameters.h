// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <string>

namespace pcl_wrap
{

/** \brief Every tunable of the Wrap construction, with its default written once here.
  *
  * The PCL class, the command-line tool and the ROS node all read their defaults from this
  * struct, so that no default is written twice.
  */
struct WrapParameters
{
  /** \brief Keep the whole complex (every Delaunay simplex with its class and whether it is in X)
    * in the result. Costs memory proportional to the triangulation; the surface W is always kept. */
  bool keep_complex = true;

  /** \brief Worker threads for the parallel stages; 0 lets TBB choose (all cores). The result does
    * not depend on it. */
  unsigned num_threads = 0;

  /** \brief Every weight is multiplied by this before use. A weight is a squared radius: the
    * power distance from point p is |x - p|^2 - w_p. */
  double weight_scale = 1.0;

  /** \brief The point field that holds the weights (e.g. "intensity" or "curvature"), read by
    * the PCL class, the command-line tool and the ROS node; empty: no weights (all 0). */
  std::string weight_field;
};

} // namespace pcl_wrap
