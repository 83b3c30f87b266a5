// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/points_apart.h"

#include "surface/solid_join.h"
#include "util/distance.h"
#include "util/parallel_for_each.h"
#include "util/union_find.h"

#include <algorithm>
#include <limits>

namespace pcl_wrap::detail
{

static_assert (APART_CLUSTER + 1 == FRAGMENT_VERTICES, "a group apart has fewer points than an object");

namespace
{

double
edgeLength (const SimplicialComplex& complex, const std::vector<Point3>& positions, SimplexId e)
{
  return distance (positions[complex.vertex (1, e, 0)], positions[complex.vertex (1, e, 1)]);
}

} // namespace

SampleGroups
sampleGroups (const SimplicialComplex& complex, const std::vector<Point3>& positions)
{
  SampleGroups out;
  const std::uint32_t n = complex.numVertices ();
  const SimplexId edges = complex.size (1);
  if (n < 5)
    return out;
  const auto length = [&] (SimplexId e) { return edgeLength (complex, positions, e); };
  // Each point's nearest neighbour, one of its Delaunay neighbours; the sample's median spacing.
  out.nearest.assign (n, std::numeric_limits<double>::infinity ());
  for (SimplexId e = 0; e < edges; ++e)
  {
    const std::uint32_t a = complex.vertex (1, e, 0), b = complex.vertex (1, e, 1);
    const double d = length (e);
    out.nearest[a] = std::min (out.nearest[a], d);
    out.nearest[b] = std::min (out.nearest[b], d);
  }
  std::vector<double> spacings (out.nearest);
  const auto middle = spacings.begin () + std::ptrdiff_t (n / 2);
  std::nth_element (spacings.begin (), middle, spacings.end ());
  const double far = APART_SPACINGS * *middle;
  std::vector<double> ().swap (spacings);
  // The groups: tied by edges no longer than that, far at the scale of the whole sample (a mesh's
  // vertices, sparse on its flat parts, can be far apart at the scale of some of their
  // neighbours). Found on all threads.
  UnionFind groups;
  groups.resetInParallel (n);
  parallelForEach (edges, [&] (std::size_t e) {
    if (length (SimplexId (e)) <= far)
      groups.uniteConcurrently (complex.vertex (1, SimplexId (e), 0), complex.vertex (1, SimplexId (e), 1));
  });
  out.group.resize (n);
  parallelForEach (n, [&] (std::size_t v) { out.group[v] = groups.findConcurrently (static_cast<std::uint32_t> (v)); });
  out.size.assign (n, 0);
  for (std::uint32_t g : out.group)
    out.count += out.size[g]++ == 0;
  return out;
}

std::vector<std::uint8_t>
pointsApart (const SimplicialComplex& complex, const std::vector<Point3>& positions, const SampleGroups& groups)
{
  const std::uint32_t n = complex.numVertices ();
  const SimplexId edges = complex.size (1);
  const std::vector<std::uint32_t>& group = groups.group;
  const std::vector<std::uint32_t>& size = groups.size;
  const std::vector<double>& nearest = groups.nearest;
  if (group.empty () ||
      std::none_of (size.begin (), size.end (), [] (std::uint32_t s) { return s > 0 && s <= APART_CLUSTER; }))
    return {};
  const auto length = [&] (SimplexId e) { return edgeLength (complex, positions, e); };
  // Per small group: its distance to the nearest point of an object (a group larger than
  // APART_CLUSTER), its Delaunay neighbours outside (counted once per edge) and those of them that
  // are points of an object more than APART_SPACINGS times nearer their own nearest point. A
  // point inside the group's hull may have no neighbour outside: the group is apart or not as a
  // whole. Small groups with no object beside them (a few blobs of points, all far apart) are
  // what the points show, and none is apart. A neighbour that is apart itself says nothing of the
  // sample around a group: far outliers whose Delaunay neighbours are mostly each other are
  // judged again by the others, and one whose neighbours are all apart is apart, until no more
  // is.
  std::vector<double> out (n, std::numeric_limits<double>::infinity ());
  for (SimplexId e = 0; e < edges; ++e)
  {
    const std::uint32_t a = complex.vertex (1, e, 0), b = complex.vertex (1, e, 1);
    for (const auto& [g, w] : {std::pair (group[a], b), std::pair (group[b], a)})
      if (size[g] <= APART_CLUSTER && size[group[w]] > APART_CLUSTER)
        out[g] = std::min (out[g], length (e));
  }
  // An object is never apart, so only the counts change from one round to the next.
  std::vector<std::uint8_t> group_apart (n, 0);
  std::vector<std::uint32_t> outside (n), denser (n), by_apart (n);
  for (bool more = true; more;)
  {
    std::fill (outside.begin (), outside.end (), 0u);
    std::fill (denser.begin (), denser.end (), 0u);
    std::fill (by_apart.begin (), by_apart.end (), 0u);
    for (SimplexId e = 0; e < edges; ++e)
    {
      const std::uint32_t a = complex.vertex (1, e, 0), b = complex.vertex (1, e, 1);
      const std::uint32_t group_a = group[a], group_b = group[b];
      if (group_a == group_b)
        continue;
      for (const auto& [g, w] : {std::pair (group_a, b), std::pair (group_b, a)})
        if (size[g] > APART_CLUSTER || group_apart[g])
          continue;
        else if (group_apart[group[w]])
          ++by_apart[g];
        else
        {
          ++outside[g];
          denser[g] += size[group[w]] > APART_CLUSTER && APART_SPACINGS * nearest[w] < out[g];
        }
    }
    more = false;
    for (std::uint32_t g = 0; g < n; ++g)
      if (size[g] > 0 && size[g] <= APART_CLUSTER && !group_apart[g] &&
          (4 * denser[g] > 3 * outside[g] || (outside[g] == 0 && by_apart[g] > 0)))
        more = group_apart[g] = 1;
  }
  std::vector<std::uint8_t> apart (n, 0);
  bool any = false;
  for (std::uint32_t v = 0; v < n; ++v)
  {
    apart[v] = group_apart[group[v]];
    any = any || apart[v];
  }
  return any ? apart : std::vector<std::uint8_t> ();
}

} // namespace pcl_wrap::detail
