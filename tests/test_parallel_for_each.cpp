// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The parallel loop shapes of src/detail against the sequential loops they stand for: the
// counting sort that names edges and orders tetrahedra must give the order a stable sequential
// bucket sort gives, on any number of threads, whatever the sizes.
#include "util/parallel_for_each.h"

#include <gtest/gtest.h>

#include <tbb/global_control.h>

#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

using detail::bucketInParallel;
using detail::fillInOrder;

struct Put
{
  std::size_t bucket;
  std::uint64_t item; // (i, k): which index put it, and its k-th put
};

/** Up to three puts per index into random buckets; some buckets get many, most none. */
std::vector<std::vector<Put>>
randomPuts (std::size_t n, std::size_t num_buckets, std::uint32_t seed)
{
  std::mt19937 rng (seed);
  std::vector<std::vector<Put>> puts (n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const int k = static_cast<int> (rng () % 4);
    for (int j = 0; j < k; ++j)
    {
      const std::size_t b = rng () % 8 == 0 ? num_buckets - 1 : rng () % num_buckets;
      puts[i].push_back ({b, (std::uint64_t (i) << 8) | j});
    }
  }
  return puts;
}

void
expectStableBucketSort (std::size_t n, std::size_t num_buckets, std::uint32_t seed)
{
  SCOPED_TRACE (testing::Message () << "n " << n << ", buckets " << num_buckets);
  const auto puts = randomPuts (n, num_buckets, seed);
  std::vector<std::vector<std::uint64_t>> expected (num_buckets);
  for (const auto& of_i : puts)
    for (const Put& p : of_i)
      expected[p.bucket].push_back (p.item);

  std::vector<std::size_t> begin;
  std::vector<int> finished (num_buckets, 0);
  const auto items = bucketInParallel<std::uint64_t> (
      n, num_buckets,
      [&] (std::size_t i, auto put) {
        for (const Put& p : puts[i])
          put (p.bucket, p.item);
      },
      begin,
      [&] (std::size_t b, auto first, auto last) {
        ++finished[b];
        // A bucket is whole when finish sees it.
        EXPECT_EQ (std::vector<std::uint64_t> (first, last), expected[b]) << "bucket " << b;
      });

  ASSERT_EQ (begin.size (), num_buckets + 1);
  EXPECT_EQ (begin.front (), 0u);
  EXPECT_EQ (begin.back (), items.size ());
  std::size_t mismatches = 0;
  for (std::size_t b = 0; b < num_buckets; ++b)
  {
    ASSERT_LE (begin[b], begin[b + 1]);
    mismatches += std::vector<std::uint64_t> (items.begin () + begin[b], items.begin () + begin[b + 1]) != expected[b];
    EXPECT_EQ (finished[b], 1) << "bucket " << b;
  }
  EXPECT_EQ (mismatches, 0u);
}

TEST (BucketInParallel, IsAStableBucketSortOnAnyNumberOfThreads)
{
  for (int threads : {1, 2, 4})
  {
    SCOPED_TRACE (testing::Message () << threads << " threads");
    tbb::global_control limit (tbb::global_control::max_allowed_parallelism, threads);
    // Sizes around the chunk (1024 indices) and coarse-bucket (4096 buckets) boundaries, and a
    // bucket count that needs several fine bits.
    expectStableBucketSort (0, 1, 1);
    expectStableBucketSort (0, 7, 1);
    expectStableBucketSort (1, 1, 2);
    expectStableBucketSort (1023, 1, 3);
    expectStableBucketSort (1025, 4095, 4);
    expectStableBucketSort (5000, 4097, 5);
    expectStableBucketSort (100000, 300000, 6);
    expectStableBucketSort (300000, 1 << 20, 7);
    expectStableBucketSort (2000, 5000000, 8);
  }
}

TEST (FillInOrder, WritesWhatASequentialPassWrites)
{
  for (std::size_t n : {std::size_t (0), std::size_t (1), std::size_t (65535), std::size_t (200001)})
  {
    std::vector<std::uint32_t> expected;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < i % 3; ++k)
        expected.push_back (static_cast<std::uint32_t> (i));
    std::vector<std::uint32_t> out;
    fillInOrder (
        n, [] (std::size_t i) { return i % 3; }, [&] (std::size_t total) { out.resize (total); },
        [&] (std::size_t i, std::size_t at) {
          for (std::size_t k = 0; k < i % 3; ++k)
            out[at++] = static_cast<std::uint32_t> (i);
          return at;
        });
    EXPECT_EQ (out, expected) << n << " indices";
  }
}

} // namespace
} // namespace pcl_wrap::test
