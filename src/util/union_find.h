// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/filled_in_parallel.h"
#include "util/parallel_for_each.h"
#include "util/portable.h"

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>

namespace pcl_wrap::detail
{

/** \brief Disjoint sets of the ids 0 .. n-1: union-find with path halving.
  *
  * On one thread, attach (a, b) hangs a's tree under b's root: the caller decides which root
  * names a set. On all threads at once, uniteConcurrently() and findConcurrently() keep every
  * root the lowest id of its tree, so that the sets and their names do not depend on the order in
  * which the threads link. One structure is used one way or the other, not both. */
class UnionFind
{
public:
  UnionFind () = default;
  explicit UnionFind (std::size_t n) { reset (n); }

  /** \brief n singletons again, reusing the memory. */
  void reset (std::size_t n)
  {
    parent_.resize (n);
    std::iota (parent_.begin (), parent_.end (), 0u);
  }
  /** \brief reset() on all threads, for sets as large as the mesh. */
  void resetInParallel (std::size_t n)
  {
    parent_.resize (n);
    parallelForEach (n, [&] (std::size_t a) { parent_[a] = static_cast<std::uint32_t> (a); });
  }

  std::size_t size () const { return parent_.size (); }

  std::uint32_t find (std::uint32_t a)
  {
    while (parent_[a] != a)
      a = parent_[a] = parent_[parent_[a]];
    return a;
  }

  /** \brief Hangs a's tree under b's root. */
  void attach (std::uint32_t a, std::uint32_t b) { parent_[find (a)] = find (b); }

  /** \brief Is \a a the root of its tree, the name of its set? */
  bool isRoot (std::uint32_t a) const { return parent_[a] == a; }

  /** \brief find() while other threads unite: path halving only ever points an entry further up
    * its tree. */
  std::uint32_t findConcurrently (std::uint32_t a)
  {
    for (std::uint32_t up; (up = relaxedLoad (&parent_[a])) != a;)
    {
      const std::uint32_t above = relaxedLoad (&parent_[up]);
      if (above != up)
        relaxedStore (&parent_[a], above);
      a = above;
    }
    return a;
  }

  /** \brief Joins the sets of \a a and \a b while other threads do the same: the higher root goes
    * under the lower. */
  void uniteConcurrently (std::uint32_t a, std::uint32_t b)
  {
    while (true)
    {
      a = findConcurrently (a);
      b = findConcurrently (b);
      if (a == b)
        return;
      if (a > b)
        std::swap (a, b);
      std::uint32_t expected = b; // b is still a root: hang it under the lower a
      if (relaxedCompareExchange (&parent_[b], expected, a))
        return;
    }
  }

private:
  FilledInParallel<std::uint32_t> parent_;
};

} // namespace pcl_wrap::detail
