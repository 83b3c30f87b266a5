// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// How a move changes the labelled solid's Euler characteristic (docs/surface.md §2), from the faces
// of the moved tetrahedra alone, against the characteristic counted face by face before and after.
#include "surface/solid_euler.h"
#include "surface/solid_labelling.h"
#include "support/pipeline.h"
#include "support/samplers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

/** chi of the union of the closed inside tetrahedra: its faces of each dimension, counted. */
int
eulerCharacteristic (const detail::SimplicialComplex& complex, const std::vector<std::uint8_t>& inside)
{
  const auto faces = detail::solidSubcomplex (complex, inside);
  int chi = 0;
  for (int k = 0; k <= 3; ++k)
    chi += (k % 2 ? -1 : 1) * static_cast<int> (std::count (faces[k].begin (), faces[k].end (), 1));
  return chi;
}

/** Random labellings of a cube sample, dense and sparse, and random moves, half of them kept: one
  * tetrahedron, the tetrahedra of one side in a vertex's star, or a tetrahedron with its neighbours
  * of the same side. */
TEST (SolidEuler, ChangeOfAMoveIsTheCountedChange)
{
  const Pipeline p (cubeSample (400, 3));
  const detail::SimplicialComplex& complex = p.complex;
  const std::uint32_t n = static_cast<std::uint32_t> (complex.size (3));
  std::mt19937 random (7);
  int seen[3] = {0, 0, 0}; // changes of -1, 0, +1 seen: the test covers all three
  for (double share : {0.3, 0.6, 0.9})
  {
    std::vector<std::uint8_t> inside (n);
    std::bernoulli_distribution in (share);
    for (auto& label : inside)
      label = in (random);
    detail::SolidEulerChange change (p.tetrahedra, inside);
    detail::SolidEulerChange::Scratch scratch;
    detail::Star star;
    for (int trial = 0; trial < 300; ++trial)
    {
      const std::uint32_t seed = std::uniform_int_distribution<std::uint32_t> (0, n - 1) (random);
      std::vector<std::uint32_t> moved{seed};
      if (trial % 3 == 1)
      {
        p.tetrahedra.gatherStar (complex.vertex (3, seed, trial % 4), star);
        moved.clear ();
        for (std::uint32_t t : star.tetrahedra ())
          if (inside[t] == inside[seed])
            moved.push_back (t);
      }
      else if (trial % 3 == 2)
        for (int i = 0; i < 4; ++i)
        {
          const std::uint32_t u = p.tetrahedra.neighbour (seed, i);
          if (u != detail::OUTSIDE_HULL && inside[u] == inside[seed])
            moved.push_back (u);
        }
      const int before = eulerCharacteristic (complex, inside);
      const int predicted = change (moved, scratch);
      for (std::uint32_t t : moved)
      {
        inside[t] ^= 1u;
        change.changedSide (t);
      }
      const int after = eulerCharacteristic (complex, inside);
      if (trial % 2) // every other move is undone; the others stay, and the next moves see them
        for (std::uint32_t t : moved)
        {
          inside[t] ^= 1u;
          change.changedSide (t);
        }
      ASSERT_EQ (predicted, after - before) << "trial " << trial << ", " << moved.size () << " moved";
      if (predicted >= -1 && predicted <= 1)
        ++seen[predicted + 1];
    }
  }
  EXPECT_GT (seen[0], 0);
  EXPECT_GT (seen[1], 0);
  EXPECT_GT (seen[2], 0);
}

} // namespace
} // namespace pcl_wrap::test
