// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The engine's first stages (input, triangulation, complex, classification), run one by one, so
// tests can look at what each built.
#include "wrap/boundary.h"
#include "wrap/retraction.h"
#include "wrap_engine.h"

#include <algorithm>
#include <memory>
#include <vector>

namespace pcl_wrap::test
{

using Tuple = std::vector<std::uint32_t>; // sorted vertex ids of a simplex

class Pipeline
{
  std::vector<Point3> input_;
  std::vector<double> input_weights_;
  WrapParameters parameters_;
  std::unique_ptr<detail::WrapEngine> engine_;

  static std::unique_ptr<detail::WrapEngine> classified (const std::vector<Point3>& input,
                                                         const std::vector<double>& weights,
                                                         const WrapParameters& parameters)
  {
    auto engine = std::make_unique<detail::WrapEngine> (input, weights, parameters);
    engine->selectInput ();
    engine->triangulate ();
    engine->buildComplex ();
    engine->classify ();
    return engine;
  }

public:
  /** Finite points with weights (empty: all 0). */
  explicit Pipeline (const std::vector<Point3>& input, const std::vector<double>& input_weights = {})
    : input_ (input), input_weights_ (input_weights), engine_ (classified (input_, input_weights_, parameters_))
  {
    for (PointIndex h : engine_->result ().hidden)
    {
      hidden_points.push_back (input_[h]);
      hidden_weights.push_back (input_weights_.empty () ? 0.0 : input_weights_[h]);
    }
  }
  Pipeline (const Pipeline&) = delete;
  Pipeline& operator= (const Pipeline&) = delete;

  const std::vector<Point3>& points = engine_->vertexPositions (); // per vertex id
  const std::vector<double>& weights = engine_->vertexWeights ();  // per vertex id
  std::vector<Point3> hidden_points;                               // points with an empty power cell
  std::vector<double> hidden_weights;
  const detail::SimplicialComplex& complex = engine_->complex ();
  const detail::PowerPredicates* const predicates = &engine_->predicates ();
  const detail::Classification& classification = engine_->classification ();
  /** How the tetrahedra meet (the default output only). */
  const detail::Tetrahedra& tetrahedra = engine_->tetrahedra ();

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
    detail::Subcomplex x (complex);
    detail::Retraction (x, classification).retract (seed);
    std::vector<Tuple> out;
    for (int k = 0; k <= 3; ++k)
      for (detail::SimplexId s = 0; s < complex.size (k); ++s)
        if (x.contains ({k, s}))
          out.push_back (tuple ({k, s}));
    std::sort (out.begin (), out.end ());
    return out;
  }
};

} // namespace pcl_wrap::test
