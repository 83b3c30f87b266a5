// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The solid labelling's queue against a plain one that looks for its top bucket by stepping
// down from the highest: the same tetrahedra, popped in the same order.
#include "surface/bucket_queue.h"

#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

constexpr int BUCKETS = 256;

class PlainQueue
{
public:
  void push (int bucket, std::uint32_t t) { stacks_[bucket].push_back (t); }
  int top () const
  {
    for (int b = BUCKETS - 1; b >= 0; --b)
      if (!stacks_[b].empty ())
        return b;
    return -1;
  }
  std::uint32_t pop (int bucket)
  {
    const std::uint32_t t = stacks_[bucket].back ();
    stacks_[bucket].pop_back ();
    return t;
  }

private:
  std::vector<std::vector<std::uint32_t>> stacks_ = std::vector<std::vector<std::uint32_t>> (BUCKETS);
};

/** Pushes and pops at random, each push to one of \a buckets, on both queues; the pops, per queue. */
std::pair<std::vector<std::pair<int, std::uint32_t>>, std::vector<std::pair<int, std::uint32_t>>>
popsOf (const std::vector<int>& buckets, unsigned seed)
{
  std::mt19937 random (seed);
  detail::BucketQueue<BUCKETS> queue;
  PlainQueue plain;
  std::pair<std::vector<std::pair<int, std::uint32_t>>, std::vector<std::pair<int, std::uint32_t>>> pops;
  std::uint32_t next = 0;
  for (int step = 0; step < 20000; ++step)
  {
    if (random () % 100 < 55)
    {
      const int b = buckets[random () % buckets.size ()];
      queue.push (b, next);
      plain.push (b, next);
      ++next;
      continue;
    }
    const int b = queue.top (), c = plain.top ();
    if (b >= 0)
      pops.first.emplace_back (b, queue.pop (b));
    if (c >= 0)
      pops.second.emplace_back (c, plain.pop (c));
  }
  for (int b = queue.top (); b >= 0; b = queue.top ())
    pops.first.emplace_back (b, queue.pop (b));
  for (int c = plain.top (); c >= 0; c = plain.top ())
    pops.second.emplace_back (c, plain.pop (c));
  return pops;
}

TEST (BucketQueue, PopsAsAPlainSearchForTheTopBucketDoes)
{
  // Buckets at the ends of words, far apart, all of them, and a band with a far top, as the flood's.
  const std::vector<std::vector<int>> patterns = {
      {0, 63, 64, 127, 128, 255}, {3, 200}, {0, 255}, {17}, {130, 131, 132, 133, 255}};
  std::vector<int> all;
  for (int b = 0; b < BUCKETS; ++b)
    all.push_back (b);
  for (unsigned seed = 1; seed <= 20; ++seed)
    for (const std::vector<int>& buckets : patterns)
    {
      const auto [queue, plain] = popsOf (buckets, seed);
      ASSERT_EQ (queue, plain) << "seed " << seed;
      ASSERT_FALSE (queue.empty ());
    }
  const auto [queue, plain] = popsOf (all, 7);
  EXPECT_EQ (queue, plain);
}

TEST (BucketQueue, IsEmptyAfterRelease)
{
  detail::BucketQueue<BUCKETS> queue;
  queue.push (200, 1);
  queue.push (5, 2);
  EXPECT_EQ (queue.top (), 200);
  queue.release ();
  EXPECT_EQ (queue.top (), -1);
  queue.push (64, 3);
  EXPECT_EQ (queue.top (), 64);
  EXPECT_EQ (queue.pop (64), 3u);
  EXPECT_EQ (queue.top (), -1);
}

} // namespace
} // namespace pcl_wrap::test
