// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_euler.h"

#include <algorithm>

namespace pcl_wrap::detail
{

namespace
{

bool
isMoved (const std::vector<std::uint32_t>& moved, std::uint32_t t)
{
  return std::binary_search (moved.begin (), moved.end (), t);
}

} // namespace

SolidEulerChange::SolidEulerChange (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside)
  : tetrahedra_ (tetrahedra), inside_ (inside), inside_at_vertex_ (tetrahedra.complex ().numVertices (), 0)
{
  for (std::uint32_t t = 0; t < inside_.size (); ++t)
    if (inside_[t])
      for (int i = 0; i < 4; ++i)
        ++inside_at_vertex_[tetrahedra_.vertex (t, i)];
}

bool
SolidEulerChange::onOtherInside (const Face& face, const std::vector<std::uint32_t>& moved) const
{
  const auto counts = [&] (std::uint32_t t) { return t != OUTSIDE_HULL && inside_[t] && !isMoved (moved, t); };
  if (face.dim == 0) // the inside tetrahedra at the vertex, less the moved ones among them
    return inside_at_vertex_[tetrahedra_.vertex (face.tetrahedron, face.a)] >
           (inside_[face.tetrahedron] ? face.uses : 0u);
  // An edge: walk its ring of tetrahedra, one way round, and the other way when the hull stops it.
  const std::uint32_t start = face.tetrahedron;
  if (counts (start))
    return true;
  const std::uint32_t a = tetrahedra_.vertex (start, face.a), b = tetrahedra_.vertex (start, face.b);
  int first = 0;
  while (first == face.a || first == face.b)
    ++first;
  for (int leave : {first, tetrahedra_.otherFacetRoundEdge (start, first, a, b)})
    for (std::uint32_t t = start;;)
    {
      const std::uint32_t u = tetrahedra_.neighbour (t, leave);
      if (u == OUTSIDE_HULL)
        break;
      if (u == start)
        return false;
      if (counts (u))
        return true;
      leave = tetrahedra_.otherFacetRoundEdge (u, tetrahedra_.mirrorIndex (t, leave), a, b);
      t = u;
    }
  return false;
}

void
SolidEulerChange::changedSide (std::uint32_t t)
{
  for (int i = 0; i < 4; ++i)
  {
    std::uint32_t& count = inside_at_vertex_[tetrahedra_.vertex (t, i)];
    count = inside_[t] ? count + 1 : count - 1;
  }
}

int
SolidEulerChange::operator() (const std::vector<std::uint32_t>& moved, Scratch& scratch) const
{
  if (moved.empty ())
    return 0;
  std::vector<std::uint32_t>& sorted = scratch.moved;
  std::vector<Face>& faces = scratch.faces;
  sorted.assign (moved.begin (), moved.end ());
  std::sort (sorted.begin (), sorted.end ());
  const SimplicialComplex& complex = tetrahedra_.complex ();
  faces.clear ();
  for (std::uint32_t t : sorted)
  {
    for (int a = 0; a < 4; ++a)
    {
      faces.push_back ({0, tetrahedra_.vertex (t, a), t, a, a, false, 1});
      const std::uint32_t u = tetrahedra_.neighbour (t, a);
      const bool across_inside = u != OUTSIDE_HULL && inside_[u] && !isMoved (sorted, u);
      faces.push_back ({2, complex.facet (3, t, a).id, t, a, a, across_inside, 1});
      for (int b = a + 1; b < 4; ++b)
        faces.push_back ({1, complex.face (3, t, (1u << a) | (1u << b)).id, t, a, b, false, 1});
    }
  }
  std::sort (faces.begin (), faces.end ());
  int chi_moved = -static_cast<int> (sorted.size ()), chi_k = 0;
  for (std::size_t i = 0; i < faces.size ();)
  {
    std::size_t j = i;
    bool in_k = false;
    for (; j < faces.size () && faces[j].dim == faces[i].dim && faces[j].id == faces[i].id; ++j)
      in_k = in_k || faces[j].in_k;
    faces[i].uses = static_cast<std::uint32_t> (j - i);
    const int sign = faces[i].dim == 1 ? -1 : 1;
    chi_moved += sign;
    if (faces[i].dim == 2 ? in_k : onOtherInside (faces[i], sorted))
      chi_k += sign;
    i = j;
  }
  return inside_[sorted.front ()] ? chi_k - chi_moved : chi_moved - chi_k;
}

} // namespace pcl_wrap::detail
