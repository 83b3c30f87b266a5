// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "wrap/classification.h"
#include "util/portable.h"

#include "util/parallel_for_each.h"
#include "delaunay/power_predicates.h"

#include <atomic>
#include <stdexcept>

namespace pcl_wrap::detail
{

Classification
classify (const SimplicialComplex& complex, const PowerPredicates& predicates)
{
  const int d = complex.dimension ();
  Classification c;
  // Per face: whether a link vertex is inside its smallest orthosphere (below).
  std::array<FilledInParallel<std::uint8_t>, 3> attached;
  for (int k = 0; k <= 3; ++k)
  {
    // Filled on all threads, not zeroed by one first: these are a few hundred megabytes at a
    // million points.
    c.classes[k].resize (complex.size (k));
    c.lowest_successor[k].resize (complex.size (k));
    c.predecessor[k].resize (k < 3 ? complex.size (k) : 0);
    if (k < 3)
      attached[k].resize (complex.size (k));
    parallelForEach (complex.size (k), [&] (std::size_t s) {
      c.classes[k][s] = SimplexClass::centered;
      c.lowest_successor[k][s] = 0;
      if (k < 3)
      {
        c.predecessor[k][s] = Simplex{-1, NO_SIMPLEX};
        attached[k][s] = 0;
      }
    });
  }
  if (d <= 0)
    return c; // no simplex but a lone vertex: a sink

  // One question per (simplex, local vertex i): is p_i inside the smallest orthosphere of the
  // facet opposite it? Its answer serves twice. For the facet it is attachment (the link
  // vertices of a face are the opposite vertices of its cofaces one dimension up, so every
  // (face, link vertex) pair is asked exactly once, whatever the number of threads). For the
  // simplex it is the sign of a barycentric coordinate: lambda_i < 0 iff the answer is yes (never
  // zero: ties are perturbed). The answers wait in lowest_successor until the classes are known.
  // With equal weights no point is inside the smallest orthosphere of another single point
  // (that needs |p - q|^2 < 0): edges ask nothing, and their midpoint is their centre.
  const bool uniform = predicates.uniformWeights ();
  for (int m = uniform ? 2 : 1; m <= d; ++m)
    parallelForEach (complex.size (m), [&] (std::size_t id) {
      const auto s = static_cast<SimplexId> (id);
      const unsigned inside = predicates.insideOppositeFacets (complex.vertices (m, s), m);
      for (unsigned rest = inside; rest != 0; rest &= rest - 1)
        relaxedStore (&attached[m - 1][complex.facet (m, s, lowestSetBit (rest)).id], std::uint8_t (1));
      c.lowest_successor[m][s] = static_cast<std::uint8_t> (inside);
    });

  // Then each simplex learns its class from its own answers and its facets' attachment, and
  // each confident one names itself the predecessor of its lowest successor. Claim 8 says no
  // two name the same; should that break, the first in (dimension, id) order keeps it, as in a
  // sequential pass, whatever the threads, and the others are counted.
  std::atomic<std::size_t> extra{0};
  const auto namePredecessor = [&] (Simplex mine) {
    const Simplex v = complex.face (mine.dim, mine.id, c.lowest_successor[mine.dim][mine.id]);
    Simplex* pred = &c.predecessor[v.dim][v.id];
    Simplex seen = relaxedLoad (pred);
    while (seen.id == NO_SIMPLEX || mine.dim < seen.dim || (mine.dim == seen.dim && mine.id < seen.id))
      if (relaxedCompareExchange (pred, seen, mine))
      {
        if (seen.id != NO_SIMPLEX)
          extra.fetch_add (1, std::memory_order_relaxed); // displaced a later one
        return;
      }
    extra.fetch_add (1, std::memory_order_relaxed); // an earlier one keeps it
  };
  for (int k = 1; k <= d; ++k)
    parallelForEach (complex.size (k), [&] (std::size_t id) {
      const auto s = static_cast<SimplexId> (id);
      const unsigned positive = fullMask (k) & ~unsigned (c.lowest_successor[k][s]);
      c.lowest_successor[k][s] = 0;
      if (k < d && attached[k][s]) // the pass that set it is over
        c.classes[k][s] = SimplexClass::equivocal;
      else if (positive == 0)
        throw std::logic_error ("classify: no positive barycentric coordinate");
      else if (positive != fullMask (k))
      {
        c.classes[k][s] = SimplexClass::confident;
        c.lowest_successor[k][s] = static_cast<std::uint8_t> (positive);
        namePredecessor ({k, s});
      }
    });
  parallelForEach (complex.size (0), [&] (std::size_t v) {
    if (attached[0][v])
      c.classes[0][v] = SimplexClass::equivocal;
  });
  c.extra_predecessors = extra.load ();
  return c;
}

} // namespace pcl_wrap::detail
