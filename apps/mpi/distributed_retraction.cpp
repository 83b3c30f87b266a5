// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "distributed_retraction.h"

#include "message_exchange.h"

#include "wrap/retraction.h"

#include <algorithm>
#include <stdexcept>

namespace pcl_wrap::mpi
{

using detail::NO_SIMPLEX;
using detail::Simplex;
using pcl_wrap::SimplexClass;

DistributedRetraction::DistributedRetraction (MPI_Comm comm, const TileComplex& tile,
                                              const detail::Classification& classification, detail::Subcomplex& y)
  : comm_ (comm), tile_ (tile), complex_ (tile.complex ()), classification_ (classification), y_ (y)
{
  int ranks = 0;
  MPI_Comm_size (comm, &ranks);
  outboxes_.resize (ranks);
}

bool
DistributedRetraction::collapsible (Simplex v) const
{
  return detail::freePair (y_, classification_, v) && tile_.belongsHere (v);
}

void
DistributedRetraction::tellOthers (Simplex xi)
{
  Removal r{xi.dim, {~0u, ~0u, ~0u, ~0u}};
  const std::uint32_t* v = complex_.vertices (xi.dim, xi.id);
  std::uint32_t told[4];
  int count = 0;
  for (int i = 0; i <= xi.dim; ++i)
    r.index[i] = tile_.indexOf (v[i]);
  for (int i = 0; i <= xi.dim; ++i)
  {
    const std::uint32_t t = tile_.tileOf (v[i]);
    if (tile_.belongsHere ({0, v[i]}) || std::find (told, told + count, t) != told + count)
      continue;
    told[count++] = t;
    outboxes_[t].push_back (r);
    ++removals_sent_;
  }
}

void
DistributedRetraction::take (Simplex xi)
{
  y_.take<false> (xi);
  for (int i = 0; xi.dim > 0 && i <= xi.dim; ++i)
  {
    const Simplex f = complex_.facet (xi.dim, xi.id, i);
    y_.loseCoface<false> (f);
    if (y_.contains (f) && tile_.belongsHere (f))
      work_.push_back (f);
  }
}

void
DistributedRetraction::collapse (Simplex tau)
{
  const unsigned low = classification_.lowest_successor[tau.dim][tau.id];
  for (unsigned mask = low; mask <= detail::fullMask (tau.dim); mask = (mask + 1) | low)
  {
    const Simplex xi = complex_.face (tau.dim, tau.id, mask);
    take (xi);
    tellOthers (xi);
  }
}

void
DistributedRetraction::retract ()
{
  for (int k = 0; k < complex_.dimension (); ++k)
    for (detail::SimplexId s = 0; s < complex_.size (k); ++s)
      if (classification_.of ({k, s}) == SimplexClass::equivocal && tile_.belongsHere ({k, s}))
        work_.push_back ({k, s});
  for (;;)
  {
    ++rounds_;
    while (!work_.empty ())
    {
      const Simplex v = work_.back ();
      work_.pop_back ();
      if (!collapsible (v))
        continue;
      collapse (classification_.predecessor[v.dim][v.id]);
      ++collapses_;
    }
    std::size_t sending = 0;
    for (const auto& box : outboxes_)
      sending += box.size ();
    const std::vector<Removal> received = allToAll (comm_, outboxes_);
    for (auto& box : outboxes_)
      box.clear ();
    for (const Removal& r : received)
    {
      const Simplex xi = tile_.find (r.dim, r.index);
      if (xi.id == NO_SIMPLEX)
        throw std::logic_error ("pcl_wrap_mpi: a removal names a simplex this tile does not hold");
      if (y_.contains (xi))
        take (xi);
    }
    if (sumOverRanks (comm_, sending) == 0)
      return;
  }
}

} // namespace pcl_wrap::mpi
