// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <pcl_wrap/compute_wrap.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The one geometric question Wrap asks, exactly and without ties.
  *
  * insideSmallestOrthosphere(T, q): is the weighted point q strictly inside the smallest sphere
  * orthogonal to the 1 to 4 weighted points T (the "smallest orthosphere" of conv T,
  * docs/design.md §2)? Both the barycentric signs (lambda_i < 0 iff p_i is inside the smallest
  * orthosphere of the opposite facet) and attachment (a link vertex inside the smallest
  * orthosphere) reduce to it.
  *
  * The answer is CGAL's exact, filtered Power_side_of_bounded_power_sphere_3. When that is
  * exactly zero, the tie is decided by the symbolic perturbation w_i - eps_i with eps_i vastly
  * larger for points later in lexicographic (x, y, z) order: the perturbation CGAL's
  * Regular_triangulation_3 uses to build the triangulation, so both describe one generic input
  * (docs/design.md §7). The predicate is affine in the weights, so the perturbed sign is read off
  * by bumping one weight at a time, from the most perturbed point down.
  */
class PowerPredicates
{
public:
  PowerPredicates (const std::vector<Point3>& positions, const std::vector<double>& weights);
  ~PowerPredicates ();
  PowerPredicates (const PowerPredicates&) = delete;
  PowerPredicates& operator= (const PowerPredicates&) = delete;

  /** \brief Is point \a q strictly inside the smallest orthosphere of the \a n (1..4) points
    * \a sphere? Never undecided. Thread-safe. */
  bool insideSmallestOrthosphere (const std::uint32_t* sphere, int n, std::uint32_t q) const;

  /** \brief The mask of the local vertices i of the simplex \a vertices (\a k + 1 of them, k = 1
    * to 3) that are inside the smallest orthosphere of the facet opposite them: the negative
    * barycentric coordinates. The same answers as insideSmallestOrthosphere, asked together so
    * that the common case is decided in one go. Thread-safe. */
  unsigned insideOppositeFacets (const std::uint32_t* vertices, int k) const;

  /** \brief Do all points have the same weight? Then no point is inside the smallest
    * orthosphere of another single point (that would need |p - q|^2 < 0): no vertex is attached
    * and no edge has a negative barycentric coordinate, and those tests need not be asked. */
  bool uniformWeights () const { return uniform_weights_; }

  /** \brief How many ties the perturbation decided so far. */
  std::size_t perturbations () const { return perturbations_.load (std::memory_order_relaxed); }

private:
  struct Points;
  std::unique_ptr<Points> points_;
  bool uniform_weights_ = true;
  mutable std::atomic<std::size_t> perturbations_{0};
};

} // namespace pcl_wrap::detail
