// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "retraction.h"

#include <random>

namespace pcl_wrap::detail
{
Retraction::Retraction (const SimplicialComplex& complex, const Classification& classification)
  : complex_ (complex), classification_ (classification)
{
  for (int k = 0; k <= 3; ++k)
    alive_[k].assign (complex.size (k), 1);
  for (int k = 0; k < 3; ++k)
    counts_[k].assign (complex.size (k), 0);
  for (int m = 1; m <= complex.dimension (); ++m)
    for (SimplexId s = 0; s < complex.size (m); ++s)
      for (int i = 0; i <= m; ++i)
        ++counts_[m - 1][complex.face (m, s, fullMask (m) & ~(1u << i)).id];
}

bool
Retraction::collapsible (Simplex v) const
{
  const Simplex tau = classification_.predecessor[v.dim][v.id];
  if (tau.id == NO_SIMPLEX || !inY (v) || !inY (tau) || classification_.of (v) != SimplexClass::equivocal)
    return false;
  // v is free with tau its largest coface iff every coface of v in Y is a face of tau. The k - l
  // faces of tau one dimension above v are in Y (Y is a complex, tau is in it), and any other
  // coface xi of v has a vertex q outside tau, so v + q is one more coface one dimension up.
  // Counting those suffices.
  return cofacesInY (v) == static_cast<std::uint32_t> (tau.dim - v.dim);
}

void
Retraction::collapse (Simplex v, Simplex tau)
{
  const unsigned low = classification_.lowest_successor[tau.dim][tau.id];
  const unsigned full = fullMask (tau.dim);
  // Remove every xi with v <= xi <= tau, and tell the facets of each that it is gone.
  for (unsigned removed = low; removed <= full; removed = (removed + 1) | low)
  {
    const Simplex xi = complex_.face (tau.dim, tau.id, removed);
    alive_[xi.dim][xi.id] = 0;
    if (xi.dim == 0)
      continue;
    for (unsigned drop = removed; drop != 0; drop &= drop - 1)
    {
      const unsigned facet = removed & ~(drop & -drop);
      const Simplex f = complex_.face (tau.dim, tau.id, facet);
      --counts_[f.dim][f.id];
      if ((facet & low) != low)
        work_.push_back (f); // survives this collapse and may have become free
    }
  }
}

std::size_t
Retraction::retract (std::uint64_t order_seed)
{
  for (int k = 0; k < complex_.dimension (); ++k)
    for (SimplexId s = 0; s < complex_.size (k); ++s)
      if (classification_.predecessor[k][s].id != NO_SIMPLEX)
        work_.push_back ({k, s});

  std::mt19937_64 random (order_seed);
  std::size_t collapses = 0;
  while (!work_.empty ())
  {
    if (order_seed != 0)
      std::swap (work_[random () % work_.size ()], work_.back ());
    const Simplex v = work_.back ();
    work_.pop_back ();
    if (collapsible (v))
    {
      collapse (v, classification_.predecessor[v.dim][v.id]);
      ++collapses;
    }
  }
  return collapses;
}

} // namespace pcl_wrap::detail
