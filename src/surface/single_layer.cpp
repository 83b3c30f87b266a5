// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/single_layer.h"

#include "surface/shell_joins.h"
#include "surface/shell_pieces.h"
#include "surface/shell_ties.h"
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
  // X's triangles on the given number of X's tetrahedra, which X counts for each (0, 1 or 2).
  const auto trianglesOn = [&] (std::uint32_t tetrahedra) {
    return countInParallel (complex.size (2), [&] (std::size_t f) {
      const Simplex triangle{2, static_cast<SimplexId> (f)};
      return x.contains (triangle) && x.cofaceCount (triangle) == tetrahedra;
    });
  };
  return {trianglesOn (0), trianglesOn (1)};
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
  const auto shellOf = [&] (const std::array<std::vector<std::uint8_t>, 4>& m) {
    const Subcomplex k (complex, m);
    TwoSidedShell out;
    out.w = extractBoundary (complex, k);
    out.split = splitPinches (complex, k, out.w);
    return out;
  };
  TwoSidedShell shell = shellOf (members);
  ShellTopology now = topologyOf (shell.split.triangles);
  while (now.pieces > 1)
  {
    std::vector<Simplex> added = shellTies (tetrahedra, positions, members[1], shell.split);
    added.erase (std::remove_if (added.begin (), added.end (), [&] (Simplex s) { return members[s.dim][s.id] != 0; }),
                 added.end ());
    if (added.empty ())
      break;
    std::array<std::vector<std::uint8_t>, 4> more = members;
    for (const Simplex s : added)
      for (unsigned mask = 1; mask < (1u << (s.dim + 1)); ++mask)
      {
        const Simplex g = complex.face (s.dim, s.id, mask);
        more[g.dim][g.id] = 1;
      }
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
