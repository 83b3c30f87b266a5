// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// The text writers' numbers against a stream's: the same characters for every double (any bit
// pattern: subnormals, infinities, NaNs), float and index, and the same text in the same order
// when it is made on all threads.
#include "number_text.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>

namespace pcl_wrap::test
{
namespace
{

std::string
streamed (double x)
{
  std::ostringstream out;
  out.precision (std::numeric_limits<double>::max_digits10); // as the mesh files are written
  out << x;
  return out.str ();
}

std::string
appended (double x)
{
  std::string text;
  apps::appendReal (text, x);
  return text;
}

TEST (NumberText, RealsAsAStreamWritesThem)
{
  const double special[] = {0.0,
                            -0.0,
                            1.0,
                            -1.0,
                            0.1,
                            1e-5,
                            123456789012345678.0,
                            1e300,
                            -1e-300,
                            std::numeric_limits<double>::denorm_min (),
                            std::numeric_limits<double>::min (),
                            std::numeric_limits<double>::max (),
                            std::numeric_limits<double>::infinity (),
                            -std::numeric_limits<double>::infinity (),
                            std::numeric_limits<double>::quiet_NaN (),
                            -std::numeric_limits<double>::quiet_NaN (),
                            1.0 / 3.0,
                            255.0 / 255.0,
                            17.0 / 255.0};
  for (double x : special)
    EXPECT_EQ (appended (x), streamed (x));
  std::mt19937_64 random (5);
  std::uniform_real_distribution<double> unit (-1.0, 1.0);
  for (int i = 0; i < 100000; ++i)
  {
    const std::uint64_t bits = random ();
    double any;
    std::memcpy (&any, &bits, sizeof any);
    ASSERT_EQ (appended (any), streamed (any)) << bits;
    const double usual = unit (random);
    ASSERT_EQ (appended (usual), streamed (usual));
    const auto narrow = static_cast<float> (usual); // a normal: widened, as a stream widens it
    std::ostringstream out;
    out.precision (std::numeric_limits<double>::max_digits10);
    out << narrow;
    ASSERT_EQ (appended (narrow), out.str ());
  }
}

TEST (NumberText, IntegersAsAStreamWritesThem)
{
  for (long long n : {0ll, 1ll, -1ll, 9ll, 10ll, 4294967295ll, 4294967296ll, std::numeric_limits<long long>::max (),
                      std::numeric_limits<long long>::min ()})
  {
    std::string text;
    apps::appendInteger (text, n);
    std::ostringstream out;
    out << n;
    EXPECT_EQ (text, out.str ());
  }
}

TEST (NumberText, ParallelTextIsInOrder)
{
  // Around the sizes of a task (4,096 items) and of the tasks held at once (32 of them).
  for (std::size_t n : {std::size_t (0), std::size_t (1), std::size_t (4095), std::size_t (4097),
                        std::size_t (32 * 4096), std::size_t (32 * 4096 + 1), std::size_t (300000)})
  {
    const auto line = [] (std::size_t i, std::string& text) {
      apps::appendInteger (text, static_cast<long long> (i));
      text += i % 3 ? " x\n" : "\n";
    };
    std::string expected;
    for (std::size_t i = 0; i < n; ++i)
      line (i, expected);
    std::ostringstream out;
    apps::writeInParallel (out, n, line);
    EXPECT_EQ (out.str (), expected) << n << " items";
  }
}

} // namespace
} // namespace pcl_wrap::test
