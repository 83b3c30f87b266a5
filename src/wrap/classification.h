// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/filled_in_parallel.h"
#include "delaunay/simplicial_complex.h"

#include <pcl_wrap/wrap_result.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

class PowerPredicates;

/** \brief The class of every simplex, the lowest successor of every confident simplex and the
  * predecessor of every equivocal one (docs/design.md §3-§4). */
struct Classification
{
  std::array<FilledInParallel<SimplexClass>, 4> classes;
  /** \brief Per confident simplex: the mask of its local vertices with lambda_i > 0, which span
    * its lowest successor LS(tau). 0 for the others. */
  std::array<FilledInParallel<std::uint8_t>, 4> lowest_successor;
  /** \brief Per equivocal simplex: the confident simplex whose lowest successor it is.
    * {-1, NO_SIMPLEX} when there is none (which would break Claim 8; the tests check it never
    * happens). For dimensions 0 to 2 only: a tetrahedron has no coface to be attached to, so it
    * is never equivocal, and predecessor[3] is empty. */
  std::array<FilledInParallel<Simplex>, 4> predecessor;
  /** \brief Equivocal simplices that are the lowest successor of more than one confident
    * simplex (also a broken Claim 8; counted, not hidden). */
  std::size_t extra_predecessors = 0;

  SimplexClass of (Simplex s) const { return classes[s.dim][s.id]; }
};

/** \brief Classifies every simplex of \a complex with exact predicates (vertex ids of the
  * complex index the points of \a predicates). */
Classification
classify (const SimplicialComplex& complex, const PowerPredicates& predicates);

} // namespace pcl_wrap::detail
