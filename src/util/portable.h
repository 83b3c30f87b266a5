// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

// What the engine needs beyond standard C++17, in one place: atomic access to plain array
// elements (the arrays are filled in parallel, then read plainly), the lowest and highest set bits
// of a mask, and advice on memory pages and caches. GCC and Clang have builtins for the first two;
// with another compiler, C++20's std::atomic_ref, std::countr_zero and std::countl_zero take their
// place.

#include <cstddef>
#include <cstdint>

#if !defined(__GNUC__)
#include <atomic>
#include <bit>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace pcl_wrap::detail
{

#if defined(__GNUC__) // GCC and Clang

template <class T>
T
relaxedLoad (const T* at)
{
  T value;
  __atomic_load (at, &value, __ATOMIC_RELAXED);
  return value;
}

template <class T>
void
relaxedStore (T* at, T value)
{
  __atomic_store (at, &value, __ATOMIC_RELAXED);
}

template <class T>
T
relaxedFetchAdd (T* at, T value)
{
  return __atomic_fetch_add (at, value, __ATOMIC_RELAXED);
}

template <class T>
T
relaxedFetchSub (T* at, T value)
{
  return __atomic_fetch_sub (at, value, __ATOMIC_RELAXED);
}

/** Replaces *at by \a desired if it equals \a expected; otherwise \a expected gets *at. */
template <class T>
bool
relaxedCompareExchange (T* at, T& expected, T desired)
{
  return __atomic_compare_exchange (at, &expected, &desired, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED);
}

/** The index of the lowest set bit of \a mask, which is not 0. */
inline int
lowestSetBit (unsigned mask)
{
  return __builtin_ctz (mask);
}

/** The index of the highest set bit of \a mask, which is not 0. */
inline int
highestSetBit (std::uint64_t mask)
{
  return 63 - __builtin_clzll (mask);
}

#else

template <class T>
T
relaxedLoad (const T* at)
{
  return std::atomic_ref<T> (*const_cast<T*> (at)).load (std::memory_order_relaxed);
}

template <class T>
void
relaxedStore (T* at, T value)
{
  std::atomic_ref<T> (*at).store (value, std::memory_order_relaxed);
}

template <class T>
T
relaxedFetchAdd (T* at, T value)
{
  return std::atomic_ref<T> (*at).fetch_add (value, std::memory_order_relaxed);
}

template <class T>
T
relaxedFetchSub (T* at, T value)
{
  return std::atomic_ref<T> (*at).fetch_sub (value, std::memory_order_relaxed);
}

template <class T>
bool
relaxedCompareExchange (T* at, T& expected, T desired)
{
  return std::atomic_ref<T> (*at).compare_exchange_strong (expected, desired, std::memory_order_relaxed);
}

inline int
lowestSetBit (unsigned mask)
{
  return std::countr_zero (mask);
}

inline int
highestSetBit (std::uint64_t mask)
{
  return 63 - std::countl_zero (mask);
}

#endif

/** Asks for \a bytes at \a at to sit on huge pages where the system has them (Linux's transparent
  * huge pages); advice only, ignored elsewhere. */
inline void
adviseHugePages (void* at, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  madvise (at, bytes, MADV_HUGEPAGE);
#else
  (void) at;
  (void) bytes;
#endif
}

/** Asks for the cache line at \a at to be fetched, for a read soon; a hint only. */
inline void
prefetch (const void* at)
{
#if defined(__GNUC__)
  __builtin_prefetch (at);
#else
  (void)at;
#endif
}

} // namespace pcl_wrap::detail
