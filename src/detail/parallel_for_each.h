// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cstddef>
#include <vector>

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

/** \brief What emit(i, out) appends to \a out for every i in [0, n), in the order of i: each
  * chunk of indices fills its own vector on TBB's threads, and the chunks are joined in order,
  * so the result is that of one sequential pass. */
template <class T, class Emit>
std::vector<T>
collectInOrder (std::size_t n, const Emit& emit)
{
  constexpr std::size_t CHUNK = 1 << 16;
  std::vector<std::vector<T>> parts ((n + CHUNK - 1) / CHUNK);
  parallelForEach (parts.size (), [&] (std::size_t c) {
    for (std::size_t i = c * CHUNK; i < n && i < (c + 1) * CHUNK; ++i)
      emit (i, parts[c]);
  }, 1);
  std::size_t total = 0;
  for (const auto& part : parts)
    total += part.size ();
  std::vector<T> all;
  all.reserve (total);
  for (auto& part : parts)
    all.insert (all.end (), part.begin (), part.end ());
  return all;
}

} // namespace pcl_wrap::detail
