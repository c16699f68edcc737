// SPDX-License-Identifier: GPL-3.0-or-later
// What a progress callback saw, for the tests of long calls that report:
// every fraction, and where it asked to stop.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ft::test {

struct ProgressLog {
  std::vector<double> seen;
  double cancel_from = 2.0;  // the first fraction at or above it cancels
  size_t cancelled_at = 0;   // its number (1-based), 0: none yet
  static int32_t call(void* user, double f) {
    auto* log = static_cast<ProgressLog*>(user);
    log->seen.push_back(f);
    if (log->cancelled_at == 0 && f >= log->cancel_from) log->cancelled_at = log->seen.size();
    return log->cancelled_at != 0;
  }
};

// The bar moves steadily: at least `calls` reports, never backwards, none
// more than `widest` past the one before, ending at 1.
inline void expect_rises_to_one_in_small_steps(const ProgressLog& log, size_t calls, double widest) {
  ASSERT_GE(log.seen.size(), calls);
  EXPECT_EQ(log.seen.back(), 1.0);
  double before = 0.0, step = 0.0;
  for (double f : log.seen) {
    EXPECT_GE(f, before);
    step = std::max(step, f - before);
    before = f;
  }
  EXPECT_LE(step, widest);
}

}  // namespace ft::test
