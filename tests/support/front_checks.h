// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// Front deletion (docs/design.md §6) checked from its end state.
#include "pipeline.h"

#include <cstddef>

namespace pcl_wrap::test
{

/** Runs front deletion above \a delta from the basic X of \a p, then, from the final Y, the trial
  * of every sink above delta still principal there (what the deletion may have skipped).
  * Asserts (gtest) that none of them reaches the surface W of that Y: the end state is a fixpoint.
  * Returns how many trials ran. */
std::size_t
expectFrontDeletionIsAFixpoint (const Pipeline& p, double delta);

} // namespace pcl_wrap::test
