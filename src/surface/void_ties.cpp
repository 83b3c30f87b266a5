// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/void_ties.h"

#include "surface/solid_join.h"
#include "util/distance.h"
#include "util/parallel_for_each.h"
#include "util/union_find.h"

#include <tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <array>
#include <limits>
#include <utility>

namespace pcl_wrap::detail
{
namespace
{

/** Per vertex, spacingAround() for all at once: the median of the shortest Delaunay edges at the
  * vertex and at its Delaunay neighbours, from the complex's edges. */
std::vector<double>
spacingsAround (const SimplicialComplex& complex, const std::vector<Point3>& positions)
{
  const std::uint32_t n = complex.numVertices ();
  std::vector<std::size_t> begin;
  const FilledInParallel<std::uint32_t> neighbours = bucketInParallel<std::uint32_t> (
      complex.size (1), n,
      [&] (std::size_t e, const auto& put) {
        const std::uint32_t a = complex.vertex (1, SimplexId (e), 0), b = complex.vertex (1, SimplexId (e), 1);
        put (a, b);
        put (b, a);
      },
      begin);
  std::vector<double> nearest (n, std::numeric_limits<double>::infinity ());
  parallelForEach (n, [&] (std::size_t v) {
    for (std::size_t k = begin[v]; k < begin[v + 1]; ++k)
      nearest[v] = std::min (nearest[v], distance (positions[v], positions[neighbours[k]]));
  });
  std::vector<double> around (n);
  tbb::enumerable_thread_specific<std::vector<double>> scratch;
  parallelForEach (n, [&] (std::size_t v) {
    std::vector<double>& spacings = scratch.local ();
    spacings.assign (1, nearest[v]);
    for (std::size_t k = begin[v]; k < begin[v + 1]; ++k)
      spacings.push_back (nearest[neighbours[k]]);
    const auto middle = spacings.begin () + std::ptrdiff_t (spacings.size () / 2);
    std::nth_element (spacings.begin (), middle, spacings.end ());
    around[v] = *middle;
  });
  return around;
}

/** Per vertex, its cluster (named by one of its vertices): the points tied by Delaunay edges
  * across no gap the sampling resolves at NECK_GAP spacings; and per cluster name, its size. */
struct Clusters
{
  std::vector<std::uint32_t> of, size;

  bool large (std::uint32_t c) const { return size[c] >= FRAGMENT_VERTICES; }
};

Clusters
clustersOf (const SimplicialComplex& complex, const std::vector<Point3>& positions)
{
  const std::uint32_t n = complex.numVertices ();
  const std::vector<double> around = spacingsAround (complex, positions);
  UnionFind sets;
  sets.resetInParallel (n);
  parallelForEach (complex.size (1), [&] (std::size_t e) {
    const std::uint32_t a = complex.vertex (1, SimplexId (e), 0), b = complex.vertex (1, SimplexId (e), 1);
    if (!resolvedGap (positions[a], positions[b], around[a], around[b], NECK_GAP))
      sets.uniteConcurrently (a, b);
  });
  Clusters out;
  out.of.resize (n);
  parallelForEach (n, [&] (std::size_t v) { out.of[v] = sets.findConcurrently (static_cast<std::uint32_t> (v)); });
  out.size.assign (n, 0);
  for (std::uint32_t c : out.of)
    ++out.size[c];
  return out;
}

} // namespace

std::vector<std::uint32_t>
cutTiesAcrossVoids (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions,
                    const std::vector<std::uint32_t>& in_voids, SolidLabels& labels, std::vector<std::uint8_t>& moved,
                    SideParts& sides)
{
  if (in_voids.empty ())
    return {};
  const Clusters clusters = clustersOf (tetrahedra.complex (), positions);
  // (cluster, void) for each large cluster on a void's surface: the corners of the facets between
  // the void's tetrahedra and the solid.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> on_void;
  std::vector<std::uint32_t> last_void (clusters.of.size (), SolidParts::NO_PART); // per cluster name
  for (std::uint32_t t : in_voids)
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = tetrahedra.neighbour (t, i);
      if (u == OUTSIDE_HULL || !labels.inside[u])
        continue;
      const std::uint32_t v = sides.part (t);
      for (int j = 1; j < 4; ++j)
      {
        const std::uint32_t c = clusters.of[tetrahedra.vertex (t, (i + j) & 3)];
        if (clusters.large (c) && last_void[c] != v)
        {
          last_void[c] = v;
          on_void.emplace_back (c, v);
        }
      }
    }
  std::sort (on_void.begin (), on_void.end ());
  on_void.erase (std::unique (on_void.begin (), on_void.end ()), on_void.end ());
  // Do clusters a and b both lie on the surface of one void?
  const auto shareAVoid = [&] (std::uint32_t a, std::uint32_t b) {
    const auto voidsOf = [&] (std::uint32_t c) {
      return std::equal_range (on_void.begin (), on_void.end (), std::make_pair (c, 0u),
                               [] (const auto& x, const auto& y) { return x.first < y.first; });
    };
    const auto [a0, a1] = voidsOf (a);
    const auto [b0, b1] = voidsOf (b);
    for (auto p = a0, q = b0; p != a1 && q != b1;)
    {
      if (p->second == q->second)
        return true;
      p->second < q->second ? ++p : ++q;
    }
    return false;
  };
  // The objects that face another across a void: a void's surface passes through two or more.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_void; // (void, cluster)
  for (const auto& [c, v] : on_void)
    by_void.emplace_back (v, c);
  std::sort (by_void.begin (), by_void.end ());
  std::vector<std::uint8_t> faces (clusters.of.size (), 0); // per cluster name
  bool any = false;
  for (std::size_t k = 0; k + 1 < by_void.size (); ++k)
    if (by_void[k].first == by_void[k + 1].first)
    {
      faces[by_void[k].second] = faces[by_void[k + 1].second] = 1;
      any = true;
    }
  if (!any)
    return {};
  const std::vector<std::uint32_t> ties = indicesWhere (tetrahedra.size (), [&] (std::size_t t) {
    if (!labels.inside[t])
      return false;
    std::array<std::uint32_t, 4> c{};
    for (int i = 0; i < 4; ++i)
      c[i] = clusters.of[tetrahedra.vertex (static_cast<std::uint32_t> (t), i)];
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (c[i] != c[j] && faces[c[i]] && faces[c[j]] && shareAVoid (c[i], c[j]))
          return true;
    return false;
  });

  // Each corner keeps an inside tetrahedron, or the cut would take a point off the surface.
  for (std::uint32_t t : ties)
    labels.inside[t] = 0;
  Star star;
  for (std::uint32_t v : tetrahedra.verticesOf (ties))
  {
    tetrahedra.gatherStar (v, star);
    if (std::none_of (star.tetrahedra ().begin (), star.tetrahedra ().end (),
                      [&] (std::uint32_t t) { return labels.inside[t] != 0; }))
    {
      for (std::uint32_t t : ties)
        labels.inside[t] = 1;
      return {};
    }
  }
  for (std::uint32_t t : ties)
    moved[t] = 1;
  // No later move ties them again (SolidLabels::oneGroup()).
  labels.facing.assign (clusters.of.size (), SolidLabels::NOT_FACING);
  for (std::uint32_t v = 0; v < clusters.of.size (); ++v)
    if (faces[clusters.of[v]])
      labels.facing[v] = clusters.of[v];
  return ties;
}

} // namespace pcl_wrap::detail
