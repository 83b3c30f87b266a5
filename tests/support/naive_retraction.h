// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// The reference retraction of docs/design.md §5: after every collapse it rescans every simplex
// for a collapsible pair and picks one at random. Quadratic; for small inputs only.
#include <pcl_wrap/wrap_result.h>

#include <cstdint>
#include <vector>

namespace pcl_wrap::test
{

struct NaiveSimplex
{
  std::vector<std::uint32_t> vertices;         // sorted
  SimplexClass cls;
  std::vector<std::uint32_t> lowest_successor; // sorted; confident simplices only
};

/** X: the simplices left when no pair is collapsible, sorted. Then, for each simplex of
  * \a deletions in turn that is still there and principal, deletes it and retracts again (§8). */
std::vector<std::vector<std::uint32_t>>
naiveRetraction (const std::vector<NaiveSimplex>& del, unsigned seed,
                 const std::vector<std::vector<std::uint32_t>>& deletions = {});

class Pipeline;

/** Del S of \a p with the classes of the exact rational reference (never the engine's); asserts
  * (gtest) that the reference met no tie. */
std::vector<NaiveSimplex>
naiveComplexWithExactClasses (const Pipeline& p);

} // namespace pcl_wrap::test
