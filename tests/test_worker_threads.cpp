// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
//
// endWorkerThreads(): a process forked after it computes on more than one thread, and computes
// what its parent computes.
#include "support/samplers.h"

#include <pcl_wrap/compute_wrap.h>
#include <pcl_wrap/worker_threads.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <thread>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

namespace pcl_wrap::test
{
namespace
{

/** The threads of this process. */
std::size_t
threadsNow ()
{
  const std::filesystem::directory_iterator tasks ("/proc/self/task");
  return static_cast<std::size_t> (std::distance (begin (tasks), end (tasks)));
}

TEST (WorkerThreads, AChildForkedAfterThemEndComputesOnMoreThanOneThread)
{
  if (std::thread::hardware_concurrency () < 2 || !std::filesystem::exists ("/proc/self/task"))
    GTEST_SKIP () << "one core, or no /proc: no worker threads to see";
  const std::vector<Point3> points = sphereSample (20000, 3);
  const WrapResult here = computeWrap (points);
  ASSERT_TRUE (endWorkerThreads ());
  const pid_t child = ::fork ();
  ASSERT_GE (child, 0);
  if (child == 0)
  {
    // Exit status: 0 when right, 1 on one thread, 2 for another surface.
    const WrapResult there = computeWrap (points);
    ::_exit (threadsNow () < 2 ? 1 : there.surface.triangles != here.surface.triangles ? 2 : 0);
  }
  int status = 0;
  ASSERT_EQ (::waitpid (child, &status, 0), child);
  ASSERT_TRUE (WIFEXITED (status));
  EXPECT_EQ (WEXITSTATUS (status), 0) << "1: the child kept one thread; 2: it computed another surface";
}

TEST (WorkerThreads, EndWithNoneStartedAndAgainAfterTheNextComputation)
{
  EXPECT_TRUE (endWorkerThreads ());
  EXPECT_TRUE (endWorkerThreads ());
  const WrapResult result = computeWrap (sphereSample (2000, 4));
  EXPECT_FALSE (result.surface.triangles.empty ());
  EXPECT_TRUE (endWorkerThreads ());
}

} // namespace
} // namespace pcl_wrap::test
