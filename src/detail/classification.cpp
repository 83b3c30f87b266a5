// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "classification.h"

#include "parallel_for_each.h"
#include "power_predicates.h"

#include <atomic>
#include <stdexcept>

namespace pcl_wrap::detail
{

Classification
classify (const SimplicialComplex& complex, const PowerPredicates& predicates)
{
  const int d = complex.dimension ();
  Classification c;
  for (int k = 0; k <= 3; ++k)
  {
    c.classes[k].assign (complex.size (k), SimplexClass::centered);
    c.lowest_successor[k].assign (complex.size (k), 0);
    c.predecessor[k].assign (k < 3 ? complex.size (k) : 0, Simplex{-1, NO_SIMPLEX});
  }
  if (d <= 0)
    return c; // no simplex but a lone vertex: a sink

  // One question per (simplex, local vertex i): is p_i inside the smallest orthosphere of the
  // facet opposite it? Its answer serves twice. For the facet it is attachment (the link
  // vertices of a face are the opposite vertices of its cofaces one dimension up, so every
  // (face, link vertex) pair is asked exactly once, whatever the number of threads). For the
  // simplex it is the sign of a barycentric coordinate: lambda_i < 0 iff the answer is yes (never
  // zero: ties are perturbed). The answers wait in lowest_successor until the classes are known.
  std::array<std::vector<std::atomic<std::uint8_t>>, 3> attached;
  for (int k = 0; k < d; ++k)
    attached[k] = std::vector<std::atomic<std::uint8_t>> (complex.size (k));
  // With equal weights no point is inside the smallest orthosphere of another single point
  // (that needs |p - q|^2 < 0): edges ask nothing, and their midpoint is their centre.
  const bool uniform = predicates.uniformWeights ();
  for (int m = uniform ? 2 : 1; m <= d; ++m)
    parallelForEach (complex.size (m), [&] (std::size_t id) {
      const auto s = static_cast<SimplexId> (id);
      const unsigned inside = predicates.insideOppositeFacets (complex.vertices (m, s), m);
      for (unsigned rest = inside; rest != 0; rest &= rest - 1)
        attached[m - 1][complex.facet (m, s, __builtin_ctz (rest)).id].store (1, std::memory_order_relaxed);
      c.lowest_successor[m][s] = static_cast<std::uint8_t> (inside);
    });

  for (int k = 1; k <= d; ++k)
    parallelForEach (complex.size (k), [&] (std::size_t id) {
      const auto s = static_cast<SimplexId> (id);
      const unsigned positive = fullMask (k) & ~unsigned (c.lowest_successor[k][s]);
      c.lowest_successor[k][s] = 0;
      if (k < d && attached[k][s].load (std::memory_order_relaxed))
        c.classes[k][s] = SimplexClass::equivocal;
      else if (positive == 0)
        throw std::logic_error ("classify: no positive barycentric coordinate");
      else if (positive != fullMask (k))
      {
        c.classes[k][s] = SimplexClass::confident;
        c.lowest_successor[k][s] = static_cast<std::uint8_t> (positive);
      }
    });
  for (SimplexId v = 0; v < complex.size (0); ++v)
    if (attached[0][v].load (std::memory_order_relaxed))
      c.classes[0][v] = SimplexClass::equivocal;

  // Each confident simplex names itself the predecessor of its lowest successor. Claim 8 says no
  // two name the same; should that break, the first in (dimension, id) order keeps it, as in a
  // sequential pass, whatever the threads, and the others are counted.
  std::atomic<std::size_t> extra{0};
  for (int k = 1; k <= d; ++k)
    parallelForEach (complex.size (k), [&] (std::size_t id) {
      const auto s = static_cast<SimplexId> (id);
      if (c.classes[k][s] != SimplexClass::confident)
        return;
      const Simplex v = complex.face (k, s, c.lowest_successor[k][s]);
      Simplex* pred = &c.predecessor[v.dim][v.id];
      Simplex mine{k, s}, seen;
      __atomic_load (pred, &seen, __ATOMIC_RELAXED);
      while (seen.id == NO_SIMPLEX || k < seen.dim || (k == seen.dim && s < seen.id))
        if (__atomic_compare_exchange (pred, &seen, &mine, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED))
        {
          if (seen.id != NO_SIMPLEX)
            extra.fetch_add (1, std::memory_order_relaxed); // displaced a later one
          return;
        }
      extra.fetch_add (1, std::memory_order_relaxed); // an earlier one keeps it
    });
  c.extra_predecessors = extra.load ();
  return c;
}

} // namespace pcl_wrap::detail
