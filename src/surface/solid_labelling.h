// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "delaunay/simplicial_complex.h"
#include "surface/bucket_queue.h"
#include "delaunay/tetrahedra.h"
#include "util/filled_in_parallel.h"
#include "wrap/subcomplex.h"

#include <pcl_wrap/compute_wrap.h>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief Which Delaunay tetrahedra are inside the solid: SolidLabelling::labels(). */
struct SolidLabels
{
  std::vector<std::uint8_t> inside; ///< per tetrahedron: 1 inside, 0 outside
  std::vector<float> margin;        ///< per tetrahedron: how much the winning vote beat the other
  bool hull = false;                ///< no vote enclosed anything: every tetrahedron is inside
  /** Per vertex: 1 for a point apart from all others (pointsApart()), which the solid leaves off
    * its surface; empty where none is. */
  std::vector<std::uint8_t> apart;

  bool isApart (std::uint32_t v) const { return !apart.empty () && apart[v]; }
  /** Per vertex: its group of the sample (SampleGroups::group), where there is more than one;
    * else empty. */
  std::vector<std::uint32_t> group;
  /** Per vertex: the object it samples (cutTiesAcrossVoids()'s clusters, named by one of their
    * vertices) where that object faces another across a void, as a ball inside a hollow sphere
    * faces the sphere's inner wall; NOT_FACING elsewhere. Empty where no object does. */
  std::vector<std::uint32_t> facing;
  static constexpr std::uint32_t NOT_FACING = ~std::uint32_t (0);

  /** Are the four vertices \a v of a tetrahedron in one group of the sample, and on at most one
    * of the objects that face each other across a void? One across the gap between two groups
    * ties separate objects, or a blob to an object: a spike; one across a void ties the objects
    * on its two sides. */
  bool oneGroup (const std::uint32_t* v) const
  {
    if (!group.empty () && (group[v[0]] != group[v[1]] || group[v[0]] != group[v[2]] || group[v[0]] != group[v[3]]))
      return false;
    if (facing.empty ())
      return true;
    std::uint32_t object = NOT_FACING;
    for (int i = 0; i < 4; ++i)
      if (facing[v[i]] != NOT_FACING)
      {
        if (object != NOT_FACING && facing[v[i]] != object)
          return false;
        object = facing[v[i]];
      }
    return true;
  }
  /** May a tetrahedron with the four vertices \a v move into the solid to bring a point on? Not
    * with a corner apart from all other points, nor across the gap between two groups: the surface
    * would reach that point, or the other group, by a spike. */
  bool mayGoInside (const std::uint32_t* v) const
  {
    return oneGroup (v) && !isApart (v[0]) && !isApart (v[1]) && !isApart (v[2]) && !isApart (v[3]);
  }
};

/** \brief Labels the Delaunay tetrahedra inside or outside the sampled solid.
  *
  * Every tetrahedron has an empty sphere (its orthosphere). Where two tetrahedra share a triangle
  * their spheres meet at an angle: spheres on one side of a sampled surface overlap deeply (they
  * fill the same part of space), spheres on opposite sides barely touch (the surface passes
  * between them). The cosine of that angle is a scale-free, parameter-free vote: same side when
  * positive, opposite sides when negative, the stronger the closer to +-1. The outside (beyond the
  * convex hull) is a half-space sphere. Starting from it, tetrahedra are labelled in order of the
  * strongest undecided vote (a priority flood, as in Amenta, Choi and Kolluri's power crust), so
  * that weak, ambiguous votes are cast last, by which time their neighbourhood is decided.
  *
  * Three steps, so that the flood, which is sequential, can run while other threads compute X:
  * the constructor computes the votes on all threads; flood() reads nothing but the votes; the
  * ties it meets (votes of exactly equal strength for both sides) wait for labels(), where Wrap's
  * X breaks them: a tetrahedron of X is inside. When no tetrahedron at all comes out inside, the
  * solid is the convex hull (SolidLabels::hull). */
class SolidLabelling
{
public:
  /** \param[in] tetrahedra four vertex ids per tetrahedron
    * \param[in] adjacency the same tetrahedra's neighbours (attach() not needed); read until
    *            labels() */
  SolidLabelling (const FilledInParallel<std::uint32_t>& tetrahedra, const Tetrahedra& adjacency,
                  const std::vector<Point3>& positions, const std::vector<double>& weights);

  /** \brief The priority flood from the outside, on the calling thread. */
  void flood ();

  /** \brief The ties broken by \a x, the flood finished, and the labels. Call once, after flood(). */
  SolidLabels labels (const Subcomplex& x);

private:
  /** Per tetrahedron, the strongest vote received so far for each side. The flood visits
    * tetrahedra in priority order, all over the mesh, and reads and writes these on every vote it
    * casts: 16 tetrahedra to a cache line. Votes and evidence are fixed point, finer than the
    * flood's buckets. */
  struct Strongest
  {
    std::uint16_t in, out;
  };
  /// Per tetrahedron, the vote cast across each facet: read once, when the tetrahedron is labelled.
  using Votes = std::array<std::int16_t, 4>;
  static constexpr int BUCKETS = 4096; ///< of the margin between the votes for the two sides

  void cast (std::uint32_t t, std::uint8_t side, int vote);
  void castFrom (std::uint32_t t);
  void prefetchNextPops (const std::vector<std::uint32_t>& bucket) const; ///< what they will read
  void run (const Subcomplex* x); ///< without X, ties are set aside
  SolidLabels labelsOf (const Subcomplex* x) const; ///< from the flood's bits; X decides the unreached
  static bool bit (const std::vector<std::uint64_t>& bits, std::uint32_t t) { return (bits[t >> 6] >> (t & 63)) & 1; }
  static void setBit (std::vector<std::uint64_t>& bits, std::uint32_t t)
  {
    bits[t >> 6] |= std::uint64_t (1) << (t & 63);
  }
  bool labelled (std::uint32_t t) const { return bit (labelled_, t); }
  bool inside (std::uint32_t t) const { return bit (inside_, t); }

  const Tetrahedra& adjacency_;
  FilledInParallel<Votes> votes_;
  FilledInParallel<Strongest> strongest_;
  /// A bit per tetrahedron, set once it is labelled (or tied): most of what the flood pops or
  /// looks at is already labelled, and these bits stay in cache where the votes do not.
  std::vector<std::uint64_t> labelled_;
  std::vector<std::uint64_t> inside_;  ///< a bit per tetrahedron, set once it is labelled inside
  BucketQueue<BUCKETS> queue_;         ///< tetrahedra by the margin between their strongest votes
  std::vector<std::uint32_t> on_hull_; ///< the tetrahedra with a facet on the hull, ascending
  std::vector<std::uint32_t> tied_;
  std::optional<SolidLabels> finished_; ///< the flood met no tie: the labels, its arrays freed
};

/** \brief The weight of a vote for the same side against one for the other side: a vote for the same
  * side counts SAME_SIDE_WEIGHT times its cosine, so a crossing (two spheres that barely touch,
  * cosine near -1) outranks any overlap, and a deep overlap a weak crossing. In a noisy layer a
  * chain of small spheres that overlap well (cosines 0.93 to 0.99) can cross the layer from the
  * outside into a thin tube and carry the outside's label through it, ahead of crossings, almost
  * as strong, that say the tube is inside (docs/surface.md, §1): the development meshes knot1 and
  * anchor_dense resampled with 10,000 points and noise of a spacing lose their tube so at 1 and
  * 0.97, and keep it at 0.95 (bench/noisy_models.py, seeds 1 to 3). */
constexpr double SAME_SIDE_WEIGHT = 0.95;

/** \brief The tetrahedra flagged in \a inside and all their faces, per dimension: the subcomplex
  * whose boundary is the surface. */
std::array<std::vector<std::uint8_t>, 4>
solidSubcomplex (const SimplicialComplex& complex, const std::vector<std::uint8_t>& inside);

/** \brief The cosine of the angle at which the spheres (centre, squared radius) \a a and \a b
  * meet, given their centres' signed heights \a ha, \a hb above a common plane through which both
  * pass in the same circle of squared radius \a rho2: (rho2 + ha hb) / (|a| |b|). +1: the same
  * sphere; -1: tangent from opposite sides. */
double
sphereAngleCosine (double rho2, double ha, double hb);

} // namespace pcl_wrap::detail
