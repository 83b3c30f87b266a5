// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/huge_pages.h"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief A number for each object of a container of STRIDE-byte objects, found from the
  * object's address alone: without reading the object.
  *
  * Reading CGAL's cells, each cell must learn the numbers of its four neighbours. Asking the
  * neighbours themselves is a random access into the whole triangulation (600 MB at a million
  * points), which waits on memory. But a container's objects lie in a few large runs of
  * consecutive addresses (CGAL's compact containers allocate them in blocks: the 6.2M cells of
  * a million points in about 900 runs), so an address names its run, and its place in it,
  * through a table small enough to stay in cache.
  *
  * Runs are the maximal sequences of objects added at consecutive addresses, so they never
  * overlap, whatever the container's layout. Add every object that will be looked up, each
  * once, then seal(), then look up.
  */
template <std::size_t STRIDE>
class AddressIndex
{
public:
  /** \brief Makes room for \a n objects. */
  void reserve (std::size_t n) { numbers_.reserve (n); }

  /** \brief Gives the object at \a object the number \a number. Cheapest when objects come in
    * increasing address order, as a container's iteration gives them. */
  void add (const void* object, std::uint32_t number)
  {
    const std::uintptr_t a = reinterpret_cast<std::uintptr_t> (object);
    if (runs_.empty () || runs_.back ().end != a)
      runs_.push_back ({a, a, numbers_.size ()});
    runs_.back ().end = a + STRIDE;
    numbers_.push_back (number);
  }

  /** \brief Builds the lookup table: runs in address order, and per page of the address range
    * (a page as large as needed to keep the table at most 2^20 entries) the first run that
    * reaches into it. */
  void seal ()
  {
    std::sort (runs_.begin (), runs_.end (), [] (const Run& x, const Run& y) { return x.begin < y.begin; });
    if (runs_.empty ())
      return;
    base_ = runs_.front ().begin;
    const std::uintptr_t last = runs_.back ().end - 1 - base_; // the last byte, from base_
    shift_ = 12;
    while ((last >> shift_) >= (std::uintptr_t (1) << 20))
      ++shift_;
    first_run_.resize ((last >> shift_) + 2);
    std::size_t r = 0;
    for (std::size_t page = 0; page < first_run_.size (); ++page)
    {
      while (r < runs_.size () && runs_[r].end <= base_ + (std::uintptr_t (page) << shift_))
        ++r;
      first_run_[page] = static_cast<std::uint32_t> (r);
    }
  }

  /** \brief The number of the object at \a object (added before seal()). */
  std::uint32_t operator[] (const void* object) const
  {
    const std::uintptr_t a = reinterpret_cast<std::uintptr_t> (object);
    assert (a >= base_ && a < runs_.back ().end);
    // The runs that reach into a's page start from first_run_[page]; the next page's first
    // run is the last that may hold a. Mostly one or two.
    const std::size_t page = (a - base_) >> shift_;
    const auto first = runs_.begin () + first_run_[page];
    const auto last = runs_.begin () + std::min<std::size_t> (first_run_[page + 1] + 1, runs_.size ());
    const auto r =
        std::upper_bound (first, last, a, [] (std::uintptr_t x, const Run& run) { return x < run.begin; }) - 1;
    assert (a >= r->begin && a < r->end && (a - r->begin) % STRIDE == 0);
    return numbers_[r->first + (a - r->begin) / STRIDE];
  }

private:
  struct Run
  {
    std::uintptr_t begin, end; // [begin, end), objects STRIDE bytes apart
    std::size_t first;         // where the number of the object at begin is in numbers_
  };
  std::vector<Run> runs_;
  HugePageVector<std::uint32_t> numbers_; // in the order added (read at random: 2 MB pages)
  std::uintptr_t base_ = 0;
  int shift_ = 12;
  std::vector<std::uint32_t> first_run_;
};

} // namespace pcl_wrap::detail
