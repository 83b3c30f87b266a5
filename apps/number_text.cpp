// SPDX-License-Identifier: GPL-3.0-or-later
// Copyright (C) 2026 the pcl_wrap authors
#include "number_text.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <charconv>
#include <limits>
#include <vector>

namespace pcl_wrap::apps
{

void
appendReal (std::string& text, double x)
{
  // std::to_chars with a precision is printf in the "C" locale, as std::num_put is.
  char digits[32];
  const auto end = std::to_chars (digits, digits + sizeof digits, x, std::chars_format::general,
                                  std::numeric_limits<double>::max_digits10)
                       .ptr;
  text.append (digits, end);
}

void
appendInteger (std::string& text, long long n)
{
  char digits[24];
  text.append (digits, std::to_chars (digits, digits + sizeof digits, n).ptr);
}

void
writeInParallel (std::ostream& out, std::size_t n, const std::function<void (std::size_t, std::string&)>& format)
{
  constexpr std::size_t ITEMS = 4096, TASKS = 32;
  std::vector<std::string> texts (TASKS);
  for (std::size_t start = 0; start < n; start += ITEMS * TASKS)
  {
    const std::size_t tasks = std::min (TASKS, (n - start + ITEMS - 1) / ITEMS);
    tbb::parallel_for (std::size_t (0), tasks, [&] (std::size_t k) {
      std::string& text = texts[k];
      text.clear ();
      const std::size_t first = start + k * ITEMS, last = std::min (n, first + ITEMS);
      for (std::size_t i = first; i < last; ++i)
        format (i, text);
    });
    for (std::size_t k = 0; k < tasks; ++k)
      out.write (texts[k].data (), std::streamsize (texts[k].size ()));
  }
}

} // namespace pcl_wrap::apps
