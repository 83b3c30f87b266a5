// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// AddressIndex, which numbers CGAL's cells by their addresses, against a map from address to
// number: objects in blocks of many sizes, with free slots, added block by block in an order
// unrelated to their addresses (as a compact container iterates).
#include "delaunay/address_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <vector>

namespace pcl_wrap::test
{
namespace
{

struct Object // the size of a CGAL cell, and not a power of two
{
  std::uint64_t words[9];
};

/** Blocks of 1 to max_block objects, every fifth slot on average free, added block by block in
  * shuffled order; checked against a map. With \a spacing 0 the blocks are allocated; otherwise
  * they are addresses \a spacing bytes apart, never read (the index must not read them). */
void
checkIndex (std::uint32_t seed, int num_blocks, int max_block, std::uintptr_t spacing = 0)
{
  std::mt19937 rng (seed);
  std::vector<std::unique_ptr<Object[]>> blocks;
  std::vector<const Object*> first;
  std::vector<int> sizes;
  for (int b = 0; b < num_blocks; ++b)
  {
    sizes.push_back (1 + static_cast<int> (rng () % max_block));
    if (spacing == 0)
      first.push_back (blocks.emplace_back (new Object[sizes.back ()]).get ());
    else
      first.push_back (reinterpret_cast<const Object*> ((std::uintptr_t (1) << 40) + b * spacing));
  }
  std::vector<int> order (num_blocks);
  std::iota (order.begin (), order.end (), 0);
  std::shuffle (order.begin (), order.end (), rng);

  detail::AddressIndex<sizeof (Object)> index;
  std::map<const Object*, std::uint32_t> expected;
  for (int b : order)
    for (int i = 0; i < sizes[b]; ++i)
      if (rng () % 5 != 0)
      {
        const Object* o = first[b] + i;
        const auto number = static_cast<std::uint32_t> (rng ());
        index.add (o, number);
        expected[o] = number;
      }
  index.seal ();
  for (const auto& [object, number] : expected)
    ASSERT_EQ (index[object], number) << "seed " << seed;
}

TEST (AddressIndex, FindsTheNumberOfEveryObjectFromItsAddress)
{
  for (std::uint32_t seed = 1; seed <= 20; ++seed)
    checkIndex (seed, 1 + seed * 7, 1 + static_cast<int> (seed * seed * 13));
}

TEST (AddressIndex, OneObject)
{
  const Object o{};
  detail::AddressIndex<sizeof (Object)> index;
  index.add (&o, 7);
  index.seal ();
  EXPECT_EQ (index[&o], 7u);
}

TEST (AddressIndex, LargeBlocksFarApart)
{
  checkIndex (99, 40, 200000);
  // Blocks 64 GB apart span far more than 2^20 pages of 4 KB: the table's pages must grow, and
  // then one page holds many runs.
  checkIndex (7, 300, 5000, std::uintptr_t (1) << 36);
}

} // namespace
} // namespace pcl_wrap::test
