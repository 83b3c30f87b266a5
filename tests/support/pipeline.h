// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The engine's stages run one by one, so tests can look at each of them.
#include "detail/boundary.h"
#include "detail/classification.h"
#include "detail/input_points.h"
#include "detail/power_predicates.h"
#include "detail/regular_triangulation.h"
#include "detail/retraction.h"
#include "detail/simplicial_complex.h"

#include <algorithm>
#include <memory>
#include <vector>

namespace pcl_wrap::test
{

using Tuple = std::vector<std::uint32_t>; // sorted vertex ids of a simplex

struct Pipeline
{
  std::vector<Point3> points;  // per vertex id
  std::vector<double> weights; // per vertex id
  std::vector<Point3> hidden_points;  // points with an empty power cell
  std::vector<double> hidden_weights;
  detail::SimplicialComplex complex;
  std::unique_ptr<detail::PowerPredicates> predicates;
  detail::Classification classification;

  /** Finite points with weights (empty: all 0). */
  explicit Pipeline (const std::vector<Point3>& input, const std::vector<double>& input_weights = {})
  {
    const detail::InputPoints s = detail::selectInputPoints (input, input_weights);
    detail::Triangulation t = detail::triangulate (s.positions, s.weights);
    for (std::uint32_t h : t.hidden)
    {
      hidden_points.push_back (s.positions[h]);
      hidden_weights.push_back (s.weights[h]);
    }
    for (std::uint32_t p : t.point_of_vertex)
    {
      points.push_back (s.positions[p]);
      weights.push_back (s.weights[p]);
    }
    complex = detail::SimplicialComplex (t.dimension, static_cast<std::uint32_t> (points.size ()), std::move (t.top_simplices), t.neighbours);
    predicates = std::make_unique<detail::PowerPredicates> (points, weights);
    classification = detail::classify (complex, *predicates);
  }

  int dimension () const { return complex.dimension (); }

  Tuple tuple (detail::Simplex s) const
  {
    Tuple t (complex.vertices (s.dim, s.id), complex.vertices (s.dim, s.id) + s.dim + 1);
    std::sort (t.begin (), t.end ());
    return t;
  }

  /** X after a retraction in the order drawn from \a seed, as one tuple per simplex. */
  std::vector<Tuple> retractedX (std::uint64_t seed = 0) const
  {
    detail::Retraction x (complex, classification);
    x.retract (seed);
    std::vector<Tuple> out;
    for (int k = 0; k <= 3; ++k)
      for (detail::SimplexId s = 0; s < complex.size (k); ++s)
        if (x.inY ({k, s}))
          out.push_back (tuple ({k, s}));
    std::sort (out.begin (), out.end ());
    return out;
  }
};

} // namespace pcl_wrap::test
