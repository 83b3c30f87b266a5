// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
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

/** \brief Writes what each i in [0, n) contributes to an output, in the order of i, on TBB's
  * threads: a first pass over chunks of indices adds up count(i), the number of items i writes;
  * resize(total) then sizes the outputs; a second pass calls write(i, offset), which writes i's
  * items from offset on and returns the offset after them. The result is that of one sequential
  * pass, with no intermediate copy. */
template <class Count, class Resize, class Write>
void
fillInOrder (std::size_t n, const Count& count, const Resize& resize, const Write& write)
{
  constexpr std::size_t CHUNK = 1 << 16;
  const std::size_t chunks = (n + CHUNK - 1) / CHUNK;
  std::vector<std::size_t> offset (chunks + 1, 0);
  parallelForEach (chunks, [&] (std::size_t c) {
    for (std::size_t i = c * CHUNK; i < n && i < (c + 1) * CHUNK; ++i)
      offset[c + 1] += count (i);
  }, 1);
  for (std::size_t c = 0; c < chunks; ++c)
    offset[c + 1] += offset[c];
  resize (offset[chunks]);
  parallelForEach (chunks, [&] (std::size_t c) {
    std::size_t at = offset[c];
    for (std::size_t i = c * CHUNK; i < n && i < (c + 1) * CHUNK; ++i)
      at = write (i, at);
  }, 1);
}

/** \brief A counting sort on TBB's threads: each (i, put) calls put (bucket, item) for the items of
  * every i in [0, n); returns the items bucket by bucket, bucket b in [begin[b], begin[b + 1]),
  * in no particular order within a bucket (sort it if the order matters). */
template <class T, class Each>
std::vector<T>
bucketInParallel (std::size_t n, std::size_t num_buckets, const Each& each, std::vector<std::size_t>& begin)
{
  std::vector<std::atomic<std::size_t>> next (num_buckets + 1);
  parallelForEach (n, [&] (std::size_t i) {
    each (i, [&] (std::size_t b, const T&) { next[b + 1].fetch_add (1, std::memory_order_relaxed); });
  });
  begin.assign (num_buckets + 1, 0);
  for (std::size_t b = 0; b < num_buckets; ++b)
  {
    begin[b + 1] = begin[b] + next[b + 1].load (std::memory_order_relaxed);
    next[b].store (begin[b], std::memory_order_relaxed);
  }
  std::vector<T> items (begin[num_buckets]);
  parallelForEach (n, [&] (std::size_t i) {
    each (i, [&] (std::size_t b, const T& item) { items[next[b].fetch_add (1, std::memory_order_relaxed)] = item; });
  });
  return items;
}

} // namespace pcl_wrap::detail
