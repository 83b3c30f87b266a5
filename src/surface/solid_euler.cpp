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
  if (face.dim == 0)
  {
    tetrahedra_.gatherStar (tetrahedra_.vertex (face.tetrahedron, face.a), star_);
    return std::any_of (star_.tetrahedra ().begin (), star_.tetrahedra ().end (), counts);
  }
  // An edge: walk its ring of tetrahedra, one way round, and the other way when the hull stops it.
  const std::uint32_t start = face.tetrahedron;
  if (counts (start))
    return true;
  int others[2], n = 0;
  for (int i = 0; i < 4; ++i)
    if (i != face.a && i != face.b)
      others[n++] = i;
  for (int way = 0; way < 2; ++way)
  {
    std::uint32_t t = start;
    int cross = others[way];                                      // the facet crossed next, opposite
    std::uint32_t kept = tetrahedra_.vertex (t, others[1 - way]); // the facet's third vertex
    for (;;)
    {
      const std::uint32_t u = tetrahedra_.neighbour (t, cross);
      if (u == OUTSIDE_HULL)
        break;
      if (u == start)
        return false;
      if (counts (u))
        return true;
      const std::uint32_t fresh = tetrahedra_.vertex (u, tetrahedra_.mirrorIndex (t, cross));
      cross = 0;
      while (tetrahedra_.vertex (u, cross) != kept)
        ++cross;
      kept = fresh;
      t = u;
    }
  }
  return false;
}

int
SolidEulerChange::operator() (const std::vector<std::uint32_t>& moved)
{
  if (moved.empty ())
    return 0;
  moved_.assign (moved.begin (), moved.end ());
  std::sort (moved_.begin (), moved_.end ());
  const SimplicialComplex& complex = tetrahedra_.complex ();
  faces_.clear ();
  for (std::uint32_t t : moved_)
  {
    for (int a = 0; a < 4; ++a)
    {
      faces_.push_back ({0, tetrahedra_.vertex (t, a), t, a, a, false});
      const std::uint32_t u = tetrahedra_.neighbour (t, a);
      const bool across_inside = u != OUTSIDE_HULL && inside_[u] && !isMoved (u);
      faces_.push_back ({2, complex.facet (3, t, a).id, t, a, a, across_inside});
      for (int b = a + 1; b < 4; ++b)
        faces_.push_back ({1, complex.face (3, t, (1u << a) | (1u << b)).id, t, a, b, false});
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
    const int sign = faces_[i].dim == 1 ? -1 : 1;
    chi_moved += sign;
    if (faces_[i].dim == 2 ? in_k : onOtherInside (faces_[i]))
      chi_k += sign;
    i = j;
  }
  return inside_[moved_.front ()] ? chi_k - chi_moved : chi_moved - chi_k;
}

} // namespace pcl_wrap::detail
