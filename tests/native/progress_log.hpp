// What a progress callback saw, for the tests of long calls: every fraction,
// and where it asked to stop. Written once, for the unit and the C ABI tests.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ft::test {

struct ProgressLog {
  std::vector<double> seen;
  double cancel_from = 2.0;  // asks to stop at the first fraction >= this
  size_t cancelled_at = 0;   // how many calls had been made when it asked (0: never)
  static int32_t call(void* user, double f) {
    auto* log = static_cast<ProgressLog*>(user);
    log->seen.push_back(f);
    if (log->cancelled_at == 0 && f >= log->cancel_from) log->cancelled_at = log->seen.size();
    return log->cancelled_at != 0;
  }
  // The widest step from 0 through the fractions seen, and whether they never fell.
  double widest_step() const {
    double before = 0.0, widest = 0.0;
    for (double f : seen) widest = std::max(widest, f - before), before = f;
    return widest;
  }
  bool rising() const { return std::is_sorted(seen.begin(), seen.end()) && (seen.empty() || seen.front() >= 0.0); }
};

}  // namespace ft::test
