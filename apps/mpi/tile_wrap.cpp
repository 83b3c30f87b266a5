// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "tile_wrap.h"

#include "wrap/boundary.h"

#include <algorithm>

namespace pcl_wrap::mpi
{

using detail::Simplex;

TileWrap
extractTileWrap (const TileComplex& tile, const detail::Subcomplex& y)
{
  const detail::SimplicialComplex& complex = tile.complex ();
  TileWrap out;
  for (int k = 0; k <= 3; ++k)
    for (detail::SimplexId s = 0; s < complex.size (k); ++s)
    {
      const Simplex simplex{k, s};
      if (!y.contains (simplex) || !tile.belongsHere (simplex))
        continue;
      const std::uint32_t* v = complex.vertices (k, s);
      ++out.x_count[k];
      if (y.cofaceCount (simplex) != 0 || k == 3)
        continue;
      if (k == 2)
        out.sheets.push_back ({tile.indexOf (v[0]), tile.indexOf (v[1]), tile.indexOf (v[2])});
      else if (k == 1)
        out.dangling_edges.push_back (
            {std::min (tile.indexOf (v[0]), tile.indexOf (v[1])), std::max (tile.indexOf (v[0]), tile.indexOf (v[1]))});
      else
        out.isolated_vertices.push_back (tile.indexOf (v[0]));
    }
  // A triangle with one tetrahedron of X behind it: written from that tetrahedron, which need
  // not belong here, when the triangle does.
  for (detail::SimplexId t = 0; t < complex.size (3); ++t)
    if (y.contains ({3, t}))
      for (int i = 0; i < 4; ++i)
      {
        const Simplex f = complex.facet (3, t, i);
        if (y.cofaceCount (f) != 1 || !tile.belongsHere (f))
          continue;
        const std::uint32_t* v = complex.vertices (3, t);
        const int* o = detail::OUTWARD_FACET[i];
        out.faces.push_back ({tile.indexOf (v[o[0]]), tile.indexOf (v[o[1]]), tile.indexOf (v[o[2]])});
      }
  return out;
}

} // namespace pcl_wrap::mpi
