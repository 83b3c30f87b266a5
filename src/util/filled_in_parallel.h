// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include "util/huge_pages.h"

#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace pcl_wrap::detail
{

/** \brief OnHugePages, except that value-initialisation (as in vector (n) and resize (n))
  * leaves trivial types uninitialised: for arrays a parallel pass fills, which would otherwise
  * first be zeroed by one thread alone. */
template <class T>
struct NoZeroing : OnHugePages<T>
{
  template <class U>
  struct rebind
  {
    using other = NoZeroing<U>;
  };
  NoZeroing () = default;
  template <class U>
  NoZeroing (const NoZeroing<U>&) noexcept {}

  template <class U>
  void construct (U* p) noexcept (std::is_nothrow_default_constructible_v<U>)
  {
    ::new (static_cast<void*> (p)) U;
  }
  template <class U, class... Args>
  void construct (U* p, Args&&... args)
  {
    ::new (static_cast<void*> (p)) U (std::forward<Args> (args)...);
  }
};

/** \brief An array that a parallel pass fills. */
template <class T>
using FilledInParallel = std::vector<T, NoZeroing<T>>;

} // namespace pcl_wrap::detail
