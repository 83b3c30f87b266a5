// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "classification.h"
#include "simplicial_complex.h"

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The subcomplex Y of Del S and the collapses that shrink it (ALGORITHM.md §5).
  *
  * Y starts as Del S with omega already deleted (omega is never counted as a coface). Every
  * simplex keeps how many of its cofaces one dimension up are still in Y, which is all freeness
  * needs (see collapsible()), and a work queue holds the only places where a new collapsible
  * pair can appear: the remaining facets of what was just removed. A whole retraction is linear
  * in the number of simplices.
  */
class Retraction
{
public:
  Retraction (const SimplicialComplex& complex, const Classification& classification);

  /** \brief Collapses while a pair is collapsible; returns the number of collapses.
    * \param[in] order_seed 0 takes work in a fixed order; any other value in a random order
    *            drawn from it (the result must not depend on it: ALGORITHM.md §5.4). */
  std::size_t retract (std::uint64_t order_seed = 0);

  bool inY (Simplex s) const { return alive_[s.dim][s.id] != 0; }
  /** \brief Number of cofaces of \a s of dimension s.dim + 1 still in Y. */
  std::uint32_t cofacesInY (Simplex s) const { return s.dim < 3 ? counts_[s.dim][s.id] : 0; }

private:
  bool collapsible (Simplex v) const;
  void collapse (Simplex v, Simplex tau);

  const SimplicialComplex& complex_;
  const Classification& classification_;
  std::array<std::vector<std::uint8_t>, 4> alive_;
  std::array<std::vector<std::uint32_t>, 3> counts_; // per k-simplex: its (k+1)-cofaces in Y
  std::vector<Simplex> work_;
};

} // namespace pcl_wrap::detail
