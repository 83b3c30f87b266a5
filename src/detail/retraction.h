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
  * simplex keeps how many of its cofaces of each higher dimension are still in Y, so freeness
  * is an O(1) test, and a work queue holds the only places where a new collapsible pair can
  * appear: the remaining faces of what was just removed. A whole retraction is linear in the
  * number of simplices.
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
  /** \brief Number of cofaces of dimension \a m (> s.dim) of \a s still in Y. */
  std::uint32_t cofacesInY (Simplex s, int m) const { return counts_[s.dim][stride (s.dim) * s.id + (m - s.dim - 1)]; }

private:
  static int stride (int k) { return 3 - k; }
  bool collapsible (Simplex v) const;
  void collapse (Simplex v, Simplex tau);

  const SimplicialComplex& complex_;
  const Classification& classification_;
  std::array<std::vector<std::uint8_t>, 4> alive_;
  std::array<std::vector<std::uint32_t>, 4> counts_; // (3 - k) per k-simplex
  std::vector<Simplex> work_;
};

} // namespace pcl_wrap::detail
