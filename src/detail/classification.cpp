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
  // are exactly the other vertices of the top simplices containing it, so one pass over the top
  // simplices tests them all. Top simplices themselves are never attached.
  std::array<std::vector<std::atomic<std::uint8_t>>, 3> attached;
  for (int k = 0; k < d; ++k)
    attached[k] = std::vector<std::atomic<std::uint8_t>> (complex.size (k));
  const bool uniform = predicates.uniformWeights ();
  forEach (complex.size (d), [&] (SimplexId t) {
    for (unsigned mask = 1; mask < fullMask (d); ++mask)
    {
      if (uniform && maskSize (mask) == 1)
        continue;
      const Simplex f = complex.face (d, t, mask);
      auto& flag = attached[f.dim][f.id];
      if (flag.load (std::memory_order_relaxed))
        continue;
      std::uint32_t sphere[4];
      const int n = gather (complex, d, t, mask, sphere);
      for (int q = 0; q <= d; ++q)
        if (!(mask & (1u << q)) && predicates.insideSmallestOrthosphere (sphere, n, complex.vertex (d, t, q)))
        {
          flag.store (1, std::memory_order_relaxed);
          break;
        }
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
