// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/subcomplex.h"

#include "util/parallel_for_each.h"

namespace pcl_wrap::detail
{

Subcomplex::Subcomplex (const SimplicialComplex& complex)
  : Subcomplex (complex, {complex.cofaceCounts (0), complex.cofaceCounts (1), complex.cofaceCounts (2)})
{}

Subcomplex::Subcomplex (const SimplicialComplex& complex, std::array<FilledInParallel<std::uint32_t>, 3> coface_counts)
  : complex_ (complex), counts_ (std::move (coface_counts))
{
  // All of Del S is in Y (omega never counts), so its coface counts are the complex's; when they
  // come empty (the complex handed its own over to another subcomplex), they are counted here.
  for (int k = 0; k <= 3; ++k)
  {
    in_[k].resize (complex.size (k));
    parallelForEach (complex.size (k), [&] (std::size_t s) { in_[k][s] = 1; });
  }
  if (counts_[0].size () != complex.size (0))
    countCofaces ();
}

Subcomplex::Subcomplex (const SimplicialComplex& complex, const std::array<std::vector<std::uint8_t>, 4>& members)
  : complex_ (complex)
{
  for (int k = 0; k <= 3; ++k)
    in_[k].assign (members[k].begin (), members[k].end ());
  countCofaces ();
}

void
Subcomplex::countCofaces ()
{
  for (int k = 0; k < 3; ++k)
    counts_[k].assign (complex_.size (k), 0);
  // In parallel: a facet is shared, so its count is bumped atomically (relaxed: only the
  // totals matter, read after the loop).
  for (int m = 1; m <= complex_.dimension (); ++m)
    parallelForEach (complex_.size (m), [&] (std::size_t id) {
      const auto s = static_cast<SimplexId> (id);
      if (in_[m][s])
        for (int i = 0; i <= m; ++i)
          relaxedFetchAdd (&counts_[m - 1][complex_.facet (m, s, i).id], 1u);
    });
}

std::size_t
Subcomplex::size (int k) const
{
  return countInParallel (complex_.size (k), [&] (std::size_t s) { return in_[k][s] != 0; });
}

void
Subcomplex::putBack (Simplex s)
{
  in_[s.dim][s.id] = 1;
  for (int i = 0; i <= s.dim && s.dim > 0; ++i)
    ++counts_[s.dim - 1][complex_.facet (s.dim, s.id, i).id];
}

} // namespace pcl_wrap::detail
