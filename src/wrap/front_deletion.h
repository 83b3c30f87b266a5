// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "wrap/classification.h"
#include "wrap/subcomplex.h"
#include "wrap/wrap_filtration.h"

#include <cstddef>

namespace pcl_wrap::detail
{

/** \brief What front deletion did. */
struct FrontDeletion
{
  std::size_t deleted = 0;       ///< sinks deleted
  std::size_t enclosed = 0;      ///< larger than delta, principal, but their basin stays inside
  std::size_t not_principal = 0; ///< larger than delta, still there, never principal
};

/** \brief "Wrap tighter" without carving cavities (docs/design.md §6, §8's G_delta with the front
  * F = all of W): after the basic retraction of \a y, deletes every sink larger than \a delta
  * whose basin (what its deletion and the retraction after it remove) reaches the current
  * surface, largest first, in passes until a pass deletes none (a deletion can expose sinks
  * behind it). A basin that stays inside uncovers the larger-than-delta sinks next to it (its
  * cosinks, §8), which are deleted with it; if even together they stay inside the solid, all of
  * it is undone.
  * \param[in] order the sinks by decreasing size, from orderSinks()
  * \param[in] in_front local modification (§8): one flag per vertex; only simplices of W whose
  *            vertices are all flagged are the front a basin must reach. Empty: all of W.
  * \param[in] order_seed as for Retraction::retract */
FrontDeletion
deleteExposedSinks (Subcomplex& y, const Classification& classification, const WrapFiltration& order, double delta,
                    const std::vector<std::uint8_t>& in_front = {}, std::uint64_t order_seed = 0);

} // namespace pcl_wrap::detail
