// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <mpi.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace pcl_wrap::mpi
{

/** \brief Sends outboxes[s] to rank s, for every rank at once, and returns what the others sent
  * this rank, in rank order. T is a plain record sent as bytes (all ranks run the same build). */
template <class T>
std::vector<T>
allToAll (MPI_Comm comm, const std::vector<std::vector<T>>& outboxes)
{
  static_assert (std::is_trivially_copyable_v<T>);
  const int ranks = static_cast<int> (outboxes.size ());
  std::vector<int> send_counts (ranks), send_offsets (ranks), receive_counts (ranks), receive_offsets (ranks);
  std::vector<T> sent;
  for (int s = 0; s < ranks; ++s)
  {
    if (outboxes[s].size () * sizeof (T) > std::size_t (std::numeric_limits<int>::max () / 2))
      throw std::runtime_error ("pcl_wrap_mpi: a message of over 1 GB between two ranks; use more ranks");
    send_offsets[s] = static_cast<int> (sent.size () * sizeof (T));
    send_counts[s] = static_cast<int> (outboxes[s].size () * sizeof (T));
    sent.insert (sent.end (), outboxes[s].begin (), outboxes[s].end ());
  }
  MPI_Alltoall (send_counts.data (), 1, MPI_INT, receive_counts.data (), 1, MPI_INT, comm);
  std::size_t total = 0;
  for (int s = 0; s < ranks; ++s)
  {
    receive_offsets[s] = static_cast<int> (total);
    total += static_cast<std::size_t> (receive_counts[s]);
  }
  std::vector<T> received (total / sizeof (T));
  MPI_Alltoallv (sent.data (), send_counts.data (), send_offsets.data (), MPI_BYTE, received.data (),
                 receive_counts.data (), receive_offsets.data (), MPI_BYTE, comm);
  return received;
}

/** \brief The sum of \a value over all ranks. */
inline std::uint64_t
sumOverRanks (MPI_Comm comm, std::uint64_t value)
{
  std::uint64_t sum = 0;
  MPI_Allreduce (&value, &sum, 1, MPI_UINT64_T, MPI_SUM, comm);
  return sum;
}

/** \brief The largest \a value over all ranks. */
inline double
largestOverRanks (MPI_Comm comm, double value)
{
  double out = 0;
  MPI_Allreduce (&value, &out, 1, MPI_DOUBLE, MPI_MAX, comm);
  return out;
}

/** \brief Every rank's \a local, concatenated in rank order, on rank 0 (empty elsewhere). */
template <class T>
std::vector<T>
gatherToRoot (MPI_Comm comm, const std::vector<T>& local)
{
  static_assert (std::is_trivially_copyable_v<T>);
  int ranks = 0;
  MPI_Comm_size (comm, &ranks);
  std::vector<std::vector<T>> outboxes (ranks);
  outboxes[0] = local;
  return allToAll (comm, outboxes);
}

/** \brief Every rank's \a local, concatenated in rank order, on every rank. */
template <class T>
std::vector<T>
allGather (MPI_Comm comm, const std::vector<T>& local)
{
  int ranks = 0;
  MPI_Comm_size (comm, &ranks);
  return allToAll (comm, std::vector<std::vector<T>> (ranks, local));
}

} // namespace pcl_wrap::mpi
