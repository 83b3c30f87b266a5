// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

namespace pcl_wrap
{

/** \brief Ends the worker threads that the parallel stages started (TBB's, shared with any other
  * TBB user in the process); the next computation starts them again.
  *
  * Call it before fork() in a process that has computed: a child forked while they live inherits
  * none of them but believes it has them, and runs every parallel stage on one thread. The Python
  * package calls it before each fork (os.register_at_fork).
  *
  * \return true when they ended (or none lived); false, at once, when they could not end because
  *         work is running on them (another thread is computing, or it was called from within a
  *         parallel stage)
  */
bool
endWorkerThreads ();

} // namespace pcl_wrap
