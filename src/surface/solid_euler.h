// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/tetrahedra.h"

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
  /** A face of a moved tetrahedron: dimension, id, where it was seen, and whether it is in K. */
  struct Face
  {
    int dim;
    std::uint32_t id;
    std::uint32_t tetrahedron;
    int a, b; // local vertices of the tetrahedron: the vertex (a), the edge (a, b)
    bool in_k;
    std::uint32_t uses; // how many moved tetrahedra have it, once sorted
    bool operator<(const Face& o) const { return dim != o.dim ? dim < o.dim : id < o.id; }
  };

public:
  /** \brief What one thread needs to weigh a move: reused from move to move. */
  struct Scratch
  {
    std::vector<std::uint32_t> moved; // sorted
    std::vector<Face> faces;
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
  /** Is some inside tetrahedron that is not in \a moved a coface of \a face? */
  bool onOtherInside (const Face& face, const std::vector<std::uint32_t>& moved) const;

  const Tetrahedra& tetrahedra_;
  const std::vector<std::uint8_t>& inside_;
  std::vector<std::uint32_t> inside_at_vertex_; // per vertex
};

} // namespace pcl_wrap::detail
