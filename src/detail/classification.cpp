// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "classification.h"

#include "power_predicates.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <stdexcept>

namespace pcl_wrap::detail
{
namespace
{

template <class F>
void
forEach (std::size_t n, const F& f)
{
  tbb::parallel_for (tbb::blocked_range<std::size_t> (0, n, 1024), [&] (const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin (); i != r.end (); ++i)
      f (static_cast<SimplexId> (i));
  });
}

/** The local vertices of (k, s) in \a mask, as vertex ids. */
int
gather (const SimplicialComplex& complex, int k, SimplexId s, unsigned mask, std::uint32_t* out)
{
  int n = 0;
  for (int i = 0; i <= k; ++i)
    if (mask & (1u << i))
      out[n++] = complex.vertex (k, s, i);
  return n;
}

/** The local vertices of (k, s) with lambda_i > 0: lambda_i < 0 iff p_i is inside the smallest
  * orthosphere of the facet opposite p_i (never zero: ties are perturbed). */
unsigned
positiveBarycentric (const SimplicialComplex& complex, const PowerPredicates& predicates, int k, SimplexId s)
{
  if (k == 1 && predicates.uniformWeights ())
    return fullMask (1); // the midpoint
  unsigned positive = 0;
  for (int i = 0; i <= k; ++i)
  {
    std::uint32_t facet[3];
    const int n = gather (complex, k, s, fullMask (k) & ~(1u << i), facet);
    if (!predicates.insideSmallestOrthosphere (facet, n, complex.vertex (k, s, i)))
      positive |= 1u << i;
  }
  return positive;
}

} // namespace

Classification
classify (const SimplicialComplex& complex, const PowerPredicates& predicates)
{
  const int d = complex.dimension ();
  Classification c;
  for (int k = 0; k <= 3; ++k)
  {
    c.classes[k].assign (complex.size (k), SimplexClass::centered);
    c.lowest_successor[k].assign (complex.size (k), 0);
    c.predecessor[k].assign (complex.size (k), Simplex{-1, NO_SIMPLEX});
  }
  if (d <= 0)
    return c; // no simplex but a lone vertex: a sink

  // Attachment: some link vertex inside the smallest orthosphere. The link vertices of a face
  // are the opposite vertices of its cofaces one dimension up, so testing every facet of every
  // simplex against the vertex opposite it asks each (face, link vertex) question exactly once:
  // the same questions whatever the number of threads.
  std::array<std::vector<std::atomic<std::uint8_t>>, 3> attached;
  for (int k = 0; k < d; ++k)
    attached[k] = std::vector<std::atomic<std::uint8_t>> (complex.size (k));
  const bool uniform = predicates.uniformWeights ();
  for (int m = uniform ? 2 : 1; m <= d; ++m)
    forEach (complex.size (m), [&] (SimplexId s) {
      for (int i = 0; i <= m; ++i)
      {
        const unsigned mask = fullMask (m) & ~(1u << i);
        std::uint32_t sphere[3];
        const int n = gather (complex, m, s, mask, sphere);
        if (predicates.insideSmallestOrthosphere (sphere, n, complex.vertex (m, s, i)))
          attached[m - 1][complex.face (m, s, mask).id].store (1, std::memory_order_relaxed);
      }
    });

  for (int k = 1; k <= d; ++k)
    forEach (complex.size (k), [&] (SimplexId s) {
      if (k < d && attached[k][s].load (std::memory_order_relaxed))
      {
        c.classes[k][s] = SimplexClass::equivocal;
        return;
      }
      const unsigned positive = positiveBarycentric (complex, predicates, k, s);
      if (positive == 0)
        throw std::logic_error ("classify: no positive barycentric coordinate");
      if (positive != fullMask (k))
      {
        c.classes[k][s] = SimplexClass::confident;
        c.lowest_successor[k][s] = static_cast<std::uint8_t> (positive);
      }
    });
  for (SimplexId v = 0; v < complex.size (0); ++v)
    if (attached[0][v].load (std::memory_order_relaxed))
      c.classes[0][v] = SimplexClass::equivocal;

  for (int k = 1; k <= d; ++k)
    for (SimplexId s = 0; s < complex.size (k); ++s)
      if (c.classes[k][s] == SimplexClass::confident)
      {
        const Simplex v = complex.face (k, s, c.lowest_successor[k][s]);
        Simplex& pred = c.predecessor[v.dim][v.id];
        if (pred.id != NO_SIMPLEX)
          ++c.extra_predecessors;
        else
          pred = Simplex{k, s};
      }
  return c;
}

} // namespace pcl_wrap::detail
