// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#pragma once

#include <cstddef>
#include <functional>
#include <ostream>
#include <string>

namespace pcl_wrap::apps
{

/** \brief Appends \a x as a stream with precision max_digits10 writes it (printf's "%.17g"): enough
  * digits to read back the same double. */
void
appendReal (std::string& text, double x);

/** \brief Appends \a n in decimal, as a stream writes it. */
void
appendInteger (std::string& text, long long n);

/** \brief Writes the text of the items [0, n) to \a out, in order, each made by \a format (i, text)
  * (which appends to text) on all threads, a few thousand items to a task and a few tasks'
  * text held at once. */
void
writeInParallel (std::ostream& out, std::size_t n, const std::function<void (std::size_t, std::string&)>& format);

} // namespace pcl_wrap::apps
