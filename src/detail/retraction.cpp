// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "retraction.h"

#include <random>

namespace pcl_wrap::detail
{
namespace
{

constexpr std::uint32_t BINOMIAL[4][4] = {{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}};

} // namespace

Retraction::Retraction (const SimplicialComplex& complex, const Classification& classification)
  : complex_ (complex), classification_ (classification)
{
  for (int k = 0; k <= 3; ++k)
  {
    alive_[k].assign (complex.size (k), 1);
    counts_[k].assign (stride (k) * complex.size (k), 0);
  }
  for (int m = 1; m <= complex.dimension (); ++m)
    for (SimplexId s = 0; s < complex.size (m); ++s)
      for (unsigned mask = 1; mask < fullMask (m); ++mask)
      {
        const Simplex f = complex.face (m, s, mask);
        ++counts_[f.dim][stride (f.dim) * f.id + (m - f.dim - 1)];
      }
}

bool
Retraction::collapsible (Simplex v) const
{
  const Simplex tau = classification_.predecessor[v.dim][v.id];
  if (tau.id == NO_SIMPLEX || !inY (v) || !inY (tau) || classification_.of (v) != SimplexClass::equivocal)
    return false;
  // v is free with tau its largest coface iff its cofaces in Y are exactly the faces of tau
  // containing it: C(k - l, m - l) of each dimension m up to k, none above.
  const int l = v.dim, k = tau.dim;
  for (int m = l + 1; m <= complex_.dimension (); ++m)
    if (cofacesInY (v, m) != (m <= k ? BINOMIAL[k - l][m - l] : 0))
      return false;
  return true;
}

void
Retraction::collapse (Simplex v, Simplex tau)
{
  const unsigned low = classification_.lowest_successor[tau.dim][tau.id];
  const unsigned full = fullMask (tau.dim);
  // Remove every xi with v <= xi <= tau, and tell the faces of each that it is gone.
  for (unsigned removed = low; removed <= full; removed = (removed + 1) | low)
  {
    const Simplex xi = complex_.face (tau.dim, tau.id, removed);
    alive_[xi.dim][xi.id] = 0;
    for (unsigned sub = (removed - 1) & removed; sub != 0; sub = (sub - 1) & removed)
    {
      const Simplex f = complex_.face (tau.dim, tau.id, sub);
      --counts_[f.dim][stride (f.dim) * f.id + (xi.dim - f.dim - 1)];
      if ((sub & low) != low)
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
