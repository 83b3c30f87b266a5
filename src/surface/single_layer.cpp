// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/single_layer.h"

#include "surface/shell_joins.h"
#include "surface/shell_pieces.h"
#include "surface/shell_ties.h"
#include "surface/solid_join.h"
#include "util/parallel_for_each.h"

#include <algorithm>
#include <array>
#include <utility>

namespace pcl_wrap::detail
{

LayerTriangles
layerTriangles (const SimplicialComplex& complex, const Subcomplex& x)
{
  if (complex.dimension () != 3)
    return {};
  // X's triangles on none and on one of X's tetrahedra, which X counts for each (0, 1 or 2), in
  // one pass on all threads.
  using Counts = std::array<std::size_t, 2>;
  const Counts counts = tbb::parallel_reduce (
      tbb::blocked_range<std::size_t> (0, complex.size (2), 4096), Counts{0, 0},
      [&] (const tbb::blocked_range<std::size_t>& r, Counts on) {
        for (std::size_t f = r.begin (); f != r.end (); ++f)
        {
          const Simplex triangle{2, static_cast<SimplexId> (f)};
          if (!x.contains (triangle))
            continue;
          const std::uint32_t tetrahedra = x.cofaceCount (triangle);
          if (tetrahedra < 2)
            ++on[tetrahedra];
        }
        return on;
      },
      [] (const Counts& a, const Counts& b) {
        return Counts{a[0] + b[0], a[1] + b[1]};
      });
  return {counts[0], counts[1]};
}

bool
isSingleLayer (const SimplicialComplex& complex, const Subcomplex& x)
{
  return layerTriangles (complex, x).singleLayer ();
}

void
addInnerTriangles (const SimplicialComplex& complex, const Subcomplex& x, Boundary& w)
{
  for (SimplexId f = 0; f < complex.size (2); ++f)
    if (x.contains ({2, f}) && x.cofaceCount ({2, f}) == 2)
    {
      const std::uint32_t* v = complex.vertices (2, f);
      w.triangles.push_back ({v[0], v[1], v[2]});
      w.triangle_ids.push_back (f);
    }
}

std::size_t
verticesOn (const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
  std::vector<std::uint32_t> v;
  v.reserve (3 * triangles.size ());
  for (const auto& t : triangles)
    v.insert (v.end (), t.begin (), t.end ());
  std::sort (v.begin (), v.end ());
  return static_cast<std::size_t> (std::unique (v.begin (), v.end ()) - v.begin ());
}

namespace
{

/** The Delaunay tetrahedra that bring onto X's boundary the points on none of its triangles that
  * a tetrahedron outside X can reach (a point that X holds by a dangling edge alone): per such
  * point v, of the tetrahedra at it whose facet opposite v is a triangle of X's boundary (on fewer
  * than two of X's tetrahedra), the one whose longest edge is shortest. Each is a tent over that
  * triangle: glued to the shell along it, a bump on the side where it stands, not a piece of its
  * own. */
std::vector<Simplex>
tentsToLonePoints (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, const Subcomplex& x)
{
  const SimplicialComplex& complex = tetrahedra.complex ();
  const auto on_boundary = [&] (SimplexId f) { return x.contains ({2, f}) && x.cofaceCount ({2, f}) < 2; };
  std::vector<std::uint8_t> on (complex.numVertices (), 0);
  for (SimplexId f = 0; f < complex.size (2); ++f)
    if (on_boundary (f))
      for (int i = 0; i < 3; ++i)
        on[complex.vertices (2, f)[i]] = 1;
  std::vector<Simplex> tents;
  Star star;
  for (std::uint32_t v = 0; v < complex.numVertices (); ++v)
  {
    if (on[v])
      continue;
    tetrahedra.gatherStar (v, star);
    std::uint32_t best = NO_TETRAHEDRON;
    double shortest = 0.0;
    for (std::uint32_t t : star.tetrahedra ())
    {
      if (x.contains ({3, t}) || !on_boundary (complex.facet (3, t, tetrahedra.localIndex (t, v)).id))
        continue;
      const double longest = longestEdge (tetrahedra, positions, t);
      if (best == NO_TETRAHEDRON || longest < shortest)
      {
        best = t;
        shortest = longest;
      }
    }
    if (best != NO_TETRAHEDRON)
      tents.push_back ({3, best});
  }
  return tents;
}

/** \a members with the simplices \a added and all their faces. */
std::array<std::vector<std::uint8_t>, 4>
withFaces (const SimplicialComplex& complex, std::array<std::vector<std::uint8_t>, 4> members,
           const std::vector<Simplex>& added)
{
  for (const Simplex s : added)
    for (unsigned mask = 1; mask < (1u << (s.dim + 1)); ++mask)
    {
      const Simplex g = complex.face (s.dim, s.id, mask);
      members[g.dim][g.id] = 1;
    }
  return members;
}

} // namespace

TwoSidedShell
twoSidedShell (const Tetrahedra& tetrahedra, const std::vector<Point3>& positions, const Subcomplex& x)
{
  const SimplicialComplex& complex = tetrahedra.complex ();
  std::array<std::vector<std::uint8_t>, 4> members;
  for (int k = 0; k <= 3; ++k)
  {
    members[k].resize (complex.size (k));
    for (SimplexId s = 0; s < members[k].size (); ++s)
      members[k][s] = x.contains ({k, s});
  }
  // A point that X holds by a dangling edge alone would be on no triangle of the shell: a tent
  // brings it on.
  const std::vector<Simplex> tents = tentsToLonePoints (tetrahedra, positions, x);
  members = withFaces (complex, std::move (members), tents);
  const auto shellOf = [&] (const std::array<std::vector<std::uint8_t>, 4>& m) {
    const Subcomplex k (complex, m);
    TwoSidedShell out;
    out.w = extractBoundary (complex, k);
    out.split = splitPinches (complex, k, out.w);
    return out;
  };
  TwoSidedShell shell = shellOf (members);
  shell.bridges = tents.size ();
  ShellTopology now = topologyOf (shell.split.triangles);
  while (now.pieces > 1)
  {
    std::vector<Simplex> added = shellTies (tetrahedra, positions, members[1], shell.split);
    added.erase (std::remove_if (added.begin (), added.end (), [&] (Simplex s) { return members[s.dim][s.id] != 0; }),
                 added.end ());
    if (added.empty ())
      break;
    std::array<std::vector<std::uint8_t>, 4> more = withFaces (complex, members, added);
    TwoSidedShell tied = shellOf (more);
    const ShellTopology then = topologyOf (tied.split.triangles);
    // A round is kept when it leaves fewer pieces and no new handle; each kept round adds
    // simplices, so the rounds end.
    if (then.pieces >= now.pieces || then.genus () > now.genus ())
      break;
    tied.bridges = shell.bridges + added.size ();
    members = std::move (more);
    shell = std::move (tied);
    now = then;
  }
  // Each pass joins pairs of the pieces it starts from; a piece joined in one may meet the next
  // one only in the next.
  std::size_t joined = 0;
  if (now.pieces > 1)
    for (std::size_t j; (j = joinAlongSharedEdges (shell.split, complex.numVertices ())) > 0;)
      joined += j;
  if (joined > 0)
    dropUnusedCopies (shell.split, complex.numVertices ());
  return shell;
}

} // namespace pcl_wrap::detail
