// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include <pcl_wrap/worker_threads.h>

#include <tbb/global_control.h>

#include <new>

namespace pcl_wrap
{

bool
endWorkerThreads ()
{
  // A handle attached to the running scheduler: finalizing it waits for its workers to exit,
  // and fails at once where that would wait on work in progress.
  tbb::task_scheduler_handle workers{tbb::attach{}};
  return tbb::finalize (workers, std::nothrow);
}

} // namespace pcl_wrap
