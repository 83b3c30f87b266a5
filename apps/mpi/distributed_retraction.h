// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "tile_complex.h"

#include "wrap/classification.h"
#include "wrap/subcomplex.h"

#include <mpi.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief The retraction of Del S to X (docs/design.md §5) over all ranks at once.
  *
  * Each rank collapses the pairs (v, tau) of the flow whose v belongs to its tile (TileComplex),
  * reading v's coface count in its own copy of Y. The intervals [v, tau] are disjoint and counts
  * only fall, so a pair that one rank sees free is free for good, and only its rank removes it:
  * the argument that lets threads collapse at once. What a rank removes, it tells every rank with
  * a vertex on it (those are the tiles of its faces), which lower their copies' counts and look
  * again at the faces that belong to them. Rounds of local collapses and one exchange go on until
  * a round sends nothing; then every rank's Y agrees with X on every simplex that belongs to it
  * and on the cofaces of those, and X is the one retraction would reach (it does not depend on
  * the order of the collapses). */
class DistributedRetraction
{
public:
  DistributedRetraction (MPI_Comm comm, const TileComplex& tile, const detail::Classification& classification,
                         detail::Subcomplex& y);

  void retract ();

  std::size_t collapses () const { return collapses_; }
  std::size_t removalsSent () const { return removals_sent_; }
  int rounds () const { return rounds_; }

private:
  /** A simplex taken out of Y, named by its vertices' indices in S (unused slots ~0). */
  struct Removal
  {
    std::int32_t dim;
    std::uint32_t index[4];
  };

  bool collapsible (detail::Simplex v) const;
  void collapse (detail::Simplex tau);
  /** Takes \a xi out of Y and lowers its facets' counts; queues those that belong here. */
  void take (detail::Simplex xi);
  void tellOthers (detail::Simplex xi);

  MPI_Comm comm_;
  const TileComplex& tile_;
  const detail::SimplicialComplex& complex_;
  const detail::Classification& classification_;
  detail::Subcomplex& y_;
  std::vector<detail::Simplex> work_;
  std::vector<std::vector<Removal>> outboxes_;
  std::size_t collapses_ = 0, removals_sent_ = 0;
  int rounds_ = 0;
};

} // namespace pcl_wrap::mpi
