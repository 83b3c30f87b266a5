// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_euler.h"

#include <algorithm>

namespace pcl_wrap::detail
{

bool
SolidEulerChange::isMoved (std::uint32_t t) const
{
  return std::binary_search (moved_.begin (), moved_.end (), t);
}

bool
SolidEulerChange::onOtherInside (const Face& face)
{
  const auto counts = [&] (std::uint32_t t) { return t != OUTSIDE_HULL && inside_[t] && !isMoved (t); };
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
  if (inside_at_vertex_.empty ())
    return;
  for (int i = 0; i < 4; ++i)
  {
    std::uint32_t& count = inside_at_vertex_[tetrahedra_.vertex (t, i)];
    count = inside_[t] ? count + 1 : count - 1;
  }
}

int
SolidEulerChange::operator() (const std::vector<std::uint32_t>& moved)
{
  if (moved.empty ())
    return 0;
  if (inside_at_vertex_.empty ())
  {
    inside_at_vertex_.assign (tetrahedra_.complex ().numVertices (), 0);
    for (std::uint32_t t = 0; t < inside_.size (); ++t)
      if (inside_[t])
        for (int i = 0; i < 4; ++i)
          ++inside_at_vertex_[tetrahedra_.vertex (t, i)];
  }
  moved_.assign (moved.begin (), moved.end ());
  std::sort (moved_.begin (), moved_.end ());
  const SimplicialComplex& complex = tetrahedra_.complex ();
  faces_.clear ();
  for (std::uint32_t t : moved_)
  {
    for (int a = 0; a < 4; ++a)
    {
      faces_.push_back ({0, tetrahedra_.vertex (t, a), t, a, a, false, 1});
      const std::uint32_t u = tetrahedra_.neighbour (t, a);
      const bool across_inside = u != OUTSIDE_HULL && inside_[u] && !isMoved (u);
      faces_.push_back ({2, complex.facet (3, t, a).id, t, a, a, across_inside, 1});
      for (int b = a + 1; b < 4; ++b)
        faces_.push_back ({1, complex.face (3, t, (1u << a) | (1u << b)).id, t, a, b, false, 1});
    }
  }
  std::sort (faces_.begin (), faces_.end ());
  int chi_moved = -static_cast<int> (moved_.size ()), chi_k = 0;
  for (std::size_t i = 0; i < faces_.size ();)
  {
    std::size_t j = i;
    bool in_k = false;
    for (; j < faces_.size () && faces_[j].dim == faces_[i].dim && faces_[j].id == faces_[i].id; ++j)
      in_k = in_k || faces_[j].in_k;
    faces_[i].uses = static_cast<std::uint32_t> (j - i);
    const int sign = faces_[i].dim == 1 ? -1 : 1;
    chi_moved += sign;
    if (faces_[i].dim == 2 ? in_k : onOtherInside (faces_[i]))
      chi_k += sign;
    i = j;
  }
  return inside_[moved_.front ()] ? chi_k - chi_moved : chi_moved - chi_k;
}

} // namespace pcl_wrap::detail
