// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/parallel_rows.hpp"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <exception>

#include "core/parallel.hpp"

namespace ft {
namespace {
constexpr int64_t kReports = 128;
}  // namespace

void for_rows(int64_t count, int threads, const Progress& progress, const std::function<void(int64_t)>& row) {
  const int team = resolve_threads(threads);
  std::atomic<int64_t> done{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
  // At most kReports reports: a callback into a script costs about as much
  // as a short row (a Blender add's 1025 rows of colours spent 40 ms in them).
  const int64_t every = std::max<int64_t>(1, (count + kReports - 1) / kReports);
#pragma omp parallel num_threads(team)
  {
    const bool caller = omp_get_thread_num() == 0;
    int64_t next = every;  // the caller's next report, in rows done
#pragma omp for schedule(dynamic, 1)
    for (int64_t k = 0; k < count; ++k) {
      if (stop.load(std::memory_order_relaxed)) continue;
      try {
        row(k);
        const int64_t d = done.fetch_add(1, std::memory_order_relaxed) + 1;
        if (caller && d >= next) {
          next = d + every;
          progress.report(double(d) / double(count));
        }
      } catch (...) {
#pragma omp critical(ft_for_rows)
        if (!error) error = std::current_exception();
        stop.store(true);
      }
    }
  }
  if (error) std::rethrow_exception(error);
  progress.report(1.0);
}

}  // namespace ft
