// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// AddressIndex, which numbers CGAL's cells by their addresses, against a map from address to
// number: objects in blocks of many sizes, with free slots, added block by block in an order
// unrelated to their addresses (as a compact container iterates).
#include "detail/address_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
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

void
checkIndex (std::uint32_t seed, int num_blocks, int max_block)
{
  std::mt19937 rng (seed);
  std::vector<std::unique_ptr<Object[]>> blocks;
  std::vector<int> sizes;
  for (int b = 0; b < num_blocks; ++b)
  {
    sizes.push_back (1 + static_cast<int> (rng () % max_block));
    blocks.emplace_back (new Object[sizes.back ()]);
  }
  std::vector<int> order (num_blocks);
  for (int b = 0; b < num_blocks; ++b)
    order[b] = b;
  std::shuffle (order.begin (), order.end (), rng);

  detail::AddressIndex<sizeof (Object)> index;
  std::map<const Object*, std::uint32_t> expected;
  for (int b : order)
    for (int i = 0; i < sizes[b]; ++i)
      if (rng () % 5 != 0) // every fifth slot, on average, free
      {
        const Object* o = &blocks[b][i];
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
  // Address ranges far wider than 2^20 small pages: the table's pages grow instead.
  checkIndex (99, 40, 200000);
}

} // namespace
} // namespace pcl_wrap::test
