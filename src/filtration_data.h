// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/classification.h"
#include "input_indices.h"
#include "delaunay/simplicial_complex.h"
#include "wrap/wrap_filtration.h"

#include <pcl_wrap/wrap_result.h>

#include <memory>
#include <vector>

namespace pcl_wrap
{

/** What a Filtration shares: the complex it was computed on and the values. */
struct Filtration::Data
{
  std::shared_ptr<const detail::SimplicialComplex> complex;
  std::shared_ptr<const detail::Classification> classification;
  std::shared_ptr<const detail::WrapFiltration> filtration;
  detail::InputIndices input_indices;
};

} // namespace pcl_wrap
