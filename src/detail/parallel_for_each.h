// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>

namespace pcl_wrap::detail
{

/** \brief Calls f(i) for every i in [0, n), on TBB's threads, in chunks of at least \a grain:
  * the one loop shape of the parallel stages (each i writes only what is its own, or uses
  * atomics). */
template <class F>
void
parallelForEach (std::size_t n, const F& f, std::size_t grain = 4096)
{
  tbb::parallel_for (tbb::blocked_range<std::size_t> (0, n, grain), [&] (const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin (); i != r.end (); ++i)
      f (i);
  });
}

} // namespace pcl_wrap::detail
