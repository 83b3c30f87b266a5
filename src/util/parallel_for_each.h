// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/filled_in_parallel.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
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

/** \brief The number of i in [0, n) for which pred(i) holds, counted on TBB's threads. */
template <class Pred>
std::size_t
countInParallel (std::size_t n, const Pred& pred)
{
  return tbb::parallel_reduce (
      tbb::blocked_range<std::size_t> (0, n, 4096), std::size_t (0),
      [&] (const tbb::blocked_range<std::size_t>& r, std::size_t count) {
        for (std::size_t i = r.begin (); i != r.end (); ++i)
          count += pred (i) ? 1 : 0;
        return count;
      },
      std::plus<> ());
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

/** \brief The i in [0, n) for which pred(i) holds, ascending, found on TBB's threads. */
template <class Pred>
std::vector<std::uint32_t>
indicesWhere (std::size_t n, const Pred& pred)
{
  std::vector<std::uint32_t> out;
  fillInOrder (
      n, [&] (std::size_t i) { return pred (i) ? 1 : 0; }, [&] (std::size_t size) { out.resize (size); },
      [&] (std::size_t i, std::size_t at) {
        if (pred (i))
          out[at++] = static_cast<std::uint32_t> (i);
        return at;
      });
  return out;
}

/** \brief Does nothing with a bucket: bucketInParallel's default last step. */
struct LeaveBucket
{
  template <class It>
  void operator() (std::size_t, It, It) const {}
};

/** \brief A stable counting sort on TBB's threads, without atomics: each (i, put) calls put (bucket,
  * item) for the items of every i in [0, n); returns the items bucket by bucket, bucket b in
  * [begin[b], begin[b + 1]), within a bucket in the order of i and put. Then \a finish (b, first,
  * last) is called on every bucket while it is still in cache (to sort it, say).
  *
  * Two levels. Runs of 2^shift consecutive buckets form a few thousand coarse buckets, so that
  * each chunk of indices counts its items per coarse bucket in a small histogram of its own;
  * prefix sums over (coarse bucket, chunk) place every chunk's items in order. Each coarse bucket,
  * a few hundred kilobytes, is then sorted by its fine buckets in cache. (One atomic counter per
  * bucket is slower: every put is then a cache miss the core has to wait for.) */
template <class T, class Each, class Finish = LeaveBucket>
FilledInParallel<T>
bucketInParallel (std::size_t n, std::size_t num_buckets, const Each& each, std::vector<std::size_t>& begin,
                  const Finish& finish = {})
{
  int shift = 0;
  while ((num_buckets >> shift) > 4096 && shift < 16)
    ++shift;
  const std::size_t fine_mask = (std::size_t (1) << shift) - 1;
  const std::size_t coarse = (num_buckets >> shift) + 1;
  const std::size_t chunks = std::min<std::size_t> ((n + 1023) / 1024, 256);
  const auto chunk_begin = [&] (std::size_t c) { return c * n / chunks; };

  // at[c * coarse + g]: chunk c's items in coarse bucket g, then where the next of them goes.
  std::vector<std::size_t> at (chunks * coarse, 0);
  parallelForEach (chunks, [&] (std::size_t c) {
    std::size_t* count = &at[c * coarse];
    for (std::size_t i = chunk_begin (c); i < chunk_begin (c + 1); ++i)
      each (i, [&] (std::size_t b, const T&) { ++count[b >> shift]; });
  }, 1);
  std::vector<std::size_t> coarse_begin (coarse + 1, 0);
  parallelForEach (coarse, [&] (std::size_t g) {
    for (std::size_t c = 0; c < chunks; ++c)
      coarse_begin[g + 1] += at[c * coarse + g];
  }, 256);
  for (std::size_t g = 0; g < coarse; ++g)
    coarse_begin[g + 1] += coarse_begin[g];
  parallelForEach (coarse, [&] (std::size_t g) {
    std::size_t next = coarse_begin[g];
    for (std::size_t c = 0; c < chunks; ++c)
      next += std::exchange (at[c * coarse + g], next);
  }, 256);

  FilledInParallel<T> items (coarse_begin[coarse]);
  FilledInParallel<std::uint16_t> fine (items.size ()); // each item's bucket within its coarse bucket
  parallelForEach (chunks, [&] (std::size_t c) {
    std::size_t* next = &at[c * coarse];
    for (std::size_t i = chunk_begin (c); i < chunk_begin (c + 1); ++i)
      each (i, [&] (std::size_t b, const T& item) {
        const std::size_t k = next[b >> shift]++;
        items[k] = item;
        fine[k] = static_cast<std::uint16_t> (b & fine_mask);
      });
  }, 1);
  at = {};

  begin.assign (num_buckets + 1, items.size ());
  tbb::parallel_for (tbb::blocked_range<std::size_t> (0, coarse), [&] (const tbb::blocked_range<std::size_t>& r) {
    FilledInParallel<T> sorted;
    std::vector<std::size_t> count (fine_mask + 2);
    for (std::size_t g = r.begin (); g != r.end (); ++g)
    {
      const std::size_t first = coarse_begin[g], last = coarse_begin[g + 1];
      const std::size_t low = g << shift, high = std::min (num_buckets, (g + 1) << shift);
      std::fill (count.begin (), count.end (), 0);
      for (std::size_t k = first; k < last; ++k)
        ++count[fine[k] + 1];
      for (std::size_t f = 0; f + 1 < count.size (); ++f)
        count[f + 1] += count[f];
      for (std::size_t b = low; b < high; ++b)
        begin[b] = first + count[b - low];
      sorted.resize (last - first);
      for (std::size_t k = first; k < last; ++k)
        sorted[count[fine[k]]++] = items[k];
      std::copy (sorted.begin (), sorted.end (), items.begin () + first);
      for (std::size_t b = low; b < high; ++b)
        finish (b, items.begin () + begin[b], items.begin () + (b + 1 < high ? begin[b + 1] : last));
    }
  });
  return items;
}

} // namespace pcl_wrap::detail
