// SPDX-License-Identifier: GPL-3.0-or-later
// Thread-count handling. Results never depend on the thread count: random
// numbers are keyed by position (core/rng.hpp), not drawn in order.
#pragma once

#include <omp.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/error.hpp"

namespace ft {

// How many cores other processes leave free right now (at least 1): the
// cores minus the tasks of other processes that are runnable at this
// instant (/proc/loadavg), this process's own runnable threads not counted.
// FT_THREADS_IGNORE_LOAD=1 gives all cores (for benchmarks that compare).
int cores_free_of_other_load();

// Resolves a user thread count (0 = all cores) to what OpenMP should use:
// at most the cores other processes leave free. On a busy machine an
// OpenMP team is slower than one thread: each barrier (a fluvial step has
// dozens) spin-waits for a thread the kernel descheduled (2 threads at load
// 4: 2.3-6.7 s against 1.2-1.8 s on one, issue 25). libgomp reads its wait
// policy (OMP_WAIT_POLICY, GOMP_SPINCOUNT) once, when it loads, before this
// library (and in Blender, before any add-on), so the library cannot make
// the waits passive; it takes fewer threads instead. Results never depend
// on the thread count, so this changes only the time.
inline int resolve_threads(int requested) {
  check_int_range("threads", requested, 0, 1024);
  return std::min(requested == 0 ? omp_get_max_threads() : requested, cores_free_of_other_load());
}

// The sum of f(i) for 0 <= i < n in the same bits on any thread count: each
// fixed block of indices is summed in order, then the blocks in order (an
// OpenMP reduction adds in an order that depends on the team).
template <typename F>
double ordered_sum(int64_t n, int team, F f) {
  constexpr int64_t kBlock = 1 << 16;
  const int64_t blocks = (n + kBlock - 1) / kBlock;
  std::vector<double> part(size_t(std::max<int64_t>(blocks, 0)), 0.0);
#pragma omp parallel for num_threads(team) schedule(static)
  for (int64_t b = 0; b < blocks; ++b) {
    double s = 0;
    for (int64_t i = b * kBlock, end = std::min(n, i + kBlock); i < end; ++i) s += f(i);
    part[size_t(b)] = s;
  }
  double sum = 0;
  for (const double s : part) sum += s;
  return sum;
}

}  // namespace ft
