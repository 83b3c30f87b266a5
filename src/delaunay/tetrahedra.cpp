// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "delaunay/tetrahedra.h"

#include "util/parallel_for_each.h"
#include "util/portable.h"

#include <algorithm>
#include <utility>

namespace pcl_wrap::detail
{

std::uint32_t
Star::indexOf (std::uint32_t t) const
{
  for (std::uint32_t at = home (t);; at = (at + 1) & mask ())
    if (keys_[at] == t)
      return slots_[at];
    else if (keys_[at] == NOT_IN_STAR)
      return NOT_IN_STAR;
}

void
Star::clear (std::uint32_t vertex)
{
  for (std::uint32_t at : used_)
    keys_[at] = NOT_IN_STAR;
  used_.clear ();
  tetrahedra_.clear ();
  vertex_ = vertex;
}

bool
Star::add (std::uint32_t t)
{
  if (2 * (used_.size () + 1) > keys_.size ())
    grow ();
  std::uint32_t at = home (t);
  for (; keys_[at] != NOT_IN_STAR; at = (at + 1) & mask ())
    if (keys_[at] == t)
      return false;
  keys_[at] = t;
  slots_[at] = static_cast<std::uint32_t> (tetrahedra_.size ());
  used_.push_back (at);
  tetrahedra_.push_back (t);
  return true;
}

void
Star::grow ()
{
  for (std::uint32_t at : used_)
    keys_[at] = NOT_IN_STAR;
  used_.clear ();
  keys_.assign (2 * keys_.size (), NOT_IN_STAR);
  slots_.resize (keys_.size ());
  std::vector<std::uint32_t> found;
  found.swap (tetrahedra_);
  for (std::uint32_t t : found)
    add (t);
}

Tetrahedra::Tetrahedra (FilledInParallel<std::uint32_t> neighbours) : neighbours_ (std::move (neighbours)) {}

void
Tetrahedra::attach (const SimplicialComplex& complex)
{
  complex_ = &complex;
  tetrahedron_of_vertex_.assign (complex.numVertices (), NO_TETRAHEDRON);
  parallelForEach (complex.size (3), [&] (std::size_t id) {
    const auto t = static_cast<std::uint32_t> (id);
    for (int i = 0; i < 4; ++i)
    {
      std::uint32_t* at = &tetrahedron_of_vertex_[complex.vertex (3, t, i)];
      std::uint32_t seen = relaxedLoad (at);
      while ((seen == NO_TETRAHEDRON || seen < t) && !relaxedCompareExchange (at, seen, t))
      {
      }
    }
  });
}

void
Tetrahedra::gatherStar (std::uint32_t v, Star& star) const
{
  star.clear (v);
  const std::uint32_t first = tetrahedronOf (v);
  if (first == NO_TETRAHEDRON)
    return;
  star.add (first);
  for (std::size_t k = 0; k < star.size (); ++k)
  {
    const std::uint32_t t = star[k];
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = neighbour (t, i);
      if (vertex (t, i) != v && u != OUTSIDE_HULL && star.add (u)) // across a facet that holds v
        prefetchTetrahedron (u); // read when the search reaches it, a few tetrahedra on
    }
  }
}

std::pair<std::uint32_t, unsigned>
Tetrahedra::faceAround (std::uint32_t around, const std::uint32_t* v, int n, Star& star) const
{
  gatherStar (around, star);
  for (std::uint32_t t : star.tetrahedra ())
  {
    unsigned mask = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < 4; ++j)
        if (vertex (t, j) == v[i])
          mask |= 1u << j;
    if (maskSize (mask) == n)
      return {t, mask};
  }
  return {NO_TETRAHEDRON, 0};
}

std::vector<std::uint32_t>
Tetrahedra::verticesOf (const std::vector<std::uint32_t>& ids) const
{
  std::vector<std::uint32_t> out;
  out.reserve (4 * ids.size ());
  for (std::uint32_t t : ids)
    out.insert (out.end (), vertices (t), vertices (t) + 4);
  std::sort (out.begin (), out.end ());
  out.erase (std::unique (out.begin (), out.end ()), out.end ());
  return out;
}

} // namespace pcl_wrap::detail
