// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief How moving a few tetrahedra across the surface would change the Euler characteristic of
  * the labelled solid, the union of its closed inside tetrahedra.
  *
  * With S the solid and P the moved tetrahedra, all on one side, and K the faces of P that are also
  * faces of an inside tetrahedron not in P: moving P inside changes chi (S) by chi (P) - chi (K),
  * moving it outside by chi (K) - chi (P). Zero leaves the solid's topology as it was; -1 makes a
  * handle (or joins two parts), +1 cuts one (or splits a part off). Only P's faces are looked at:
  * the tetrahedra around each edge, and a count of inside tetrahedra per vertex, kept up to date by
  * changedSide(). */
class SolidEulerChange
{
public:
  /** \brief The distinct tetrahedra, vertices or edges of a move, each with where it was first
    * seen and how many of the tetrahedra have it: a small open-addressing table, emptied in the
    * time it was filled, so that weighing a move allocates nothing once warm. */
  class DistinctFaces
  {
  public:
    struct Seen
    {
      std::uint32_t tetrahedron;
      int a, b;           ///< local vertices of the tetrahedron: the vertex (a), the edge (a, b)
      std::uint32_t uses; ///< how many of the tetrahedra have it
    };
    /** Empties the table, sized for up to \a faces distinct keys. */
    void clear (std::size_t faces);
    /** One more use of the face \a key (a vertex id, or an edge's two ids, the lower in the high
      * half), seen in \a tetrahedron at its local vertices \a a, \a b. */
    void add (std::uint64_t key, std::uint32_t tetrahedron, int a, int b);
    /** Has the face \a key been added since the table was emptied? */
    bool contains (std::uint64_t key) const;
    const std::vector<Seen>& seen () const { return seen_; }

  private:
    static constexpr std::uint64_t EMPTY = ~std::uint64_t (0);
    std::vector<std::uint64_t> keys_;
    std::vector<std::uint32_t> slot_; // per place in keys_: the face's index in seen_
    std::vector<std::uint32_t> used_; // the places filled
    std::vector<Seen> seen_;
  };

  /** \brief What one thread needs to weigh a move: reused from move to move. */
  struct Scratch
  {
    DistinctFaces moved; // the move's tetrahedra, keyed by id
    DistinctFaces faces;
  };

  /** Counts the inside tetrahedra at each vertex. */
  SolidEulerChange (const Tetrahedra& tetrahedra, const std::vector<std::uint8_t>& inside);

  /** \brief The change of chi (S) if the tetrahedra \a moved (all on one side, distinct) changed
    * side. Reads the labels and counts only, so threads may weigh moves at once, each with its own
    * \a scratch, while none changes a side. */
  int operator() (const std::vector<std::uint32_t>& moved, Scratch& scratch) const;

  /** \brief To be called after \a t changed side: keeps the count of inside tetrahedra at each
    * vertex up to date. */
  void changedSide (std::uint32_t t);

private:
  /** Is some inside tetrahedron that is not in \a moved a coface of \a edge? */
  bool edgeOnOtherInside (const DistinctFaces::Seen& edge, const DistinctFaces& moved) const;

  const Tetrahedra& tetrahedra_;
  const std::vector<std::uint8_t>& inside_;
  std::vector<std::uint32_t> inside_at_vertex_; // per vertex
};

} // namespace pcl_wrap::detail
