// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "surface/solid_euler.h"

#include <algorithm>

namespace pcl_wrap::detail
{

SolidEulerChange::SolidEulerChange (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside)
  : tetrahedra_ (tetrahedra), inside_ (inside), inside_at_vertex_ (tetrahedra.complex ().numVertices (), 0)
{
  for (std::uint32_t t = 0; t < inside_.size (); ++t)
    if (inside_[t])
      for (int i = 0; i < 4; ++i)
        ++inside_at_vertex_[tetrahedra_.vertex (t, i)];
}

void
SolidEulerChange::DistinctFaces::clear (std::size_t faces)
{
  for (std::uint32_t at : used_)
    keys_[at] = EMPTY;
  used_.clear ();
  seen_.clear ();
  std::size_t size = 64;
  while (size < 2 * faces)
    size *= 2;
  if (size > keys_.size ())
  {
    keys_.assign (size, EMPTY);
    slot_.resize (size);
  }
}

namespace
{

std::size_t
homeOf (std::uint64_t key, std::size_t mask)
{
  return static_cast<std::size_t> ((key * 0x9E3779B97F4A7C15u) >> 32) & mask;
}

} // namespace

bool
SolidEulerChange::DistinctFaces::contains (std::uint64_t key) const
{
  const std::size_t mask = keys_.size () - 1;
  for (std::size_t at = homeOf (key, mask); keys_[at] != EMPTY; at = (at + 1) & mask)
    if (keys_[at] == key)
      return true;
  return false;
}

void
SolidEulerChange::DistinctFaces::add (std::uint64_t key, std::uint32_t tetrahedron, int a, int b)
{
  const std::size_t mask = keys_.size () - 1;
  std::size_t at = homeOf (key, mask);
  for (; keys_[at] != EMPTY; at = (at + 1) & mask)
    if (keys_[at] == key)
    {
      ++seen_[slot_[at]].uses;
      return;
    }
  keys_[at] = key;
  slot_[at] = static_cast<std::uint32_t> (seen_.size ());
  used_.push_back (static_cast<std::uint32_t> (at));
  seen_.push_back ({tetrahedron, a, b, 1});
}

bool
SolidEulerChange::edgeOnOtherInside (const DistinctFaces::Seen& edge, const DistinctFaces& moved) const
{
  return tetrahedra_.anyRoundEdge (edge.tetrahedron, edge.a, edge.b,
                                   [&] (std::uint32_t t) { return inside_[t] && !moved.contains (t); });
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
  DistinctFaces& in_move = scratch.moved;
  in_move.clear (moved.size ());
  for (std::uint32_t t : moved)
    in_move.add (t, t, 0, 0);
  const bool moved_inside = inside_[moved.front ()] != 0;
  // chi (P) and chi (K), face by face: K's vertices, edges and triangles are those with an inside
  // coface not in P.
  int chi_moved = -static_cast<int> (moved.size ()), chi_k = 0;
  // Triangles: a triangle of two moved tetrahedra is counted at the lower, and is not in K; any
  // other is in K when the tetrahedron across it is inside.
  for (std::uint32_t t : moved)
    for (int i = 0; i < 4; ++i)
    {
      const std::uint32_t u = tetrahedra_.neighbour (t, i);
      if (u != OUTSIDE_HULL && in_move.contains (u))
        chi_moved += t < u;
      else
      {
        ++chi_moved;
        chi_k += u != OUTSIDE_HULL && inside_[u];
      }
    }
  // Vertices: in K when more inside tetrahedra have the vertex than the moved ones that are.
  DistinctFaces& faces = scratch.faces;
  faces.clear (4 * moved.size ());
  for (std::uint32_t t : moved)
    for (int a = 0; a < 4; ++a)
      faces.add (tetrahedra_.vertex (t, a), t, a, a);
  for (const DistinctFaces::Seen& v : faces.seen ())
  {
    ++chi_moved;
    chi_k += inside_at_vertex_[tetrahedra_.vertex (v.tetrahedron, v.a)] > (moved_inside ? v.uses : 0u);
  }
  // Edges: in K when an inside tetrahedron not moved is in the edge's ring.
  faces.clear (6 * moved.size ());
  for (std::uint32_t t : moved)
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
      {
        const std::uint64_t u = tetrahedra_.vertex (t, a), w = tetrahedra_.vertex (t, b);
        faces.add (std::min (u, w) << 32 | std::max (u, w), t, a, b);
      }
  for (const DistinctFaces::Seen& e : faces.seen ())
  {
    --chi_moved;
    chi_k -= edgeOnOtherInside (e, in_move);
  }
  return moved_inside ? chi_k - chi_moved : chi_moved - chi_k;
}

} // namespace pcl_wrap::detail
