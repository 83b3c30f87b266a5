#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# usage: bench/under_memory_cap.sh MEGABYTES COMMAND [ARGS...]
#
# Runs COMMAND in a memory cgroup of its own capped at MEGABYTES of resident memory (the kernel
# kills it past the cap, there being no swap to spill to). Under mpirun, each rank gets its own
# cap, as each node of a cluster has its own memory:
#   mpirun -np 2 bench/under_memory_cap.sh 1500 build/apps/mpi/pcl_wrap_mpi IN OUT --raw
# Needs root and the cgroup v1 memory controller (/sys/fs/cgroup/memory).
set -euo pipefail
megabytes=$1
shift
root=/sys/fs/cgroup/memory
[ -w "$root" ] || { echo "under_memory_cap.sh: no writable $root (root and cgroup v1 needed)" >&2; exit 3; }
group="$root/pcl_wrap_cap_$$"
mkdir "$group"
echo $((megabytes * 1024 * 1024)) > "$group/memory.limit_in_bytes"
# A reaper outside the group removes it once this process (the command, after exec) has ended.
main=$$
( while kill -0 "$main" 2>/dev/null; do sleep 1; done; rmdir "$group" 2>/dev/null ) </dev/null >/dev/null 2>&1 &
echo $$ > "$group/cgroup.procs"
exec "$@"
