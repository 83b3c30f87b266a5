// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/portable.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief The solid labelling's queue: BUCKETS stacks of tetrahedra, the highest bucket that
  * holds one popped first, and within a bucket the last pushed.
  *
  * The flood works in a band of buckets far below the top, and a crossing's vote lifts it to the
  * top now and then; stepping back down one empty bucket at a time would take 277 million steps on
  * 1M sphere points. A bit per bucket, set by every push and cleared once the bucket is found
  * empty, finds the next bucket down a word at a time. */
template <int BUCKETS>
class BucketQueue
{
  static_assert (BUCKETS > 0 && BUCKETS % 64 == 0, "whole words of bits");

public:
  BucketQueue () : stacks_ (BUCKETS) {}

  void push (int bucket, std::uint32_t t)
  {
    stacks_[bucket].push_back (t);
    pushed_[bucket >> 6] |= std::uint64_t (1) << (bucket & 63);
    top_ = std::max (top_, bucket);
  }

  /** The highest bucket that holds a tetrahedron; -1 when none does. */
  int top ()
  {
    while (top_ >= 0 && stacks_[top_].empty ())
    {
      pushed_[top_ >> 6] &= ~(std::uint64_t (1) << (top_ & 63));
      int word = top_ >> 6;
      std::uint64_t bits = pushed_[word] & ((std::uint64_t (2) << (top_ & 63)) - 1); // up to top_'s
      while (bits == 0 && word > 0)
        bits = pushed_[--word];
      top_ = bits == 0 ? -1 : 64 * word + highestSetBit (bits);
    }
    return top_;
  }

  /** The tetrahedra of \a bucket, the next popped last. */
  const std::vector<std::uint32_t>& stack (int bucket) const { return stacks_[bucket]; }

  /** Takes the last pushed from \a bucket, which holds one. */
  std::uint32_t pop (int bucket)
  {
    const std::uint32_t t = stacks_[bucket].back ();
    stacks_[bucket].pop_back ();
    return t;
  }

  /** Empties the queue and frees its memory. */
  void release ()
  {
    std::vector<std::vector<std::uint32_t>> (BUCKETS).swap (stacks_);
    pushed_ = {};
    top_ = -1;
  }

private:
  std::vector<std::vector<std::uint32_t>> stacks_;
  std::array<std::uint64_t, BUCKETS / 64> pushed_{};
  int top_ = -1; ///< no bucket above it holds a tetrahedron
};

} // namespace pcl_wrap::detail
