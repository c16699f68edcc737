// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/parallel_rows.hpp"

#include <omp.h>

#include <atomic>
#include <exception>

#include "core/parallel.hpp"

namespace ft {

void for_rows(int64_t count, int threads, const Progress& progress, const std::function<void(int64_t)>& row) {
  const int team = resolve_threads(threads);
  std::atomic<int64_t> done{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;
#pragma omp parallel num_threads(team)
  {
    const bool caller = omp_get_thread_num() == 0;
#pragma omp for schedule(dynamic, 1)
    for (int64_t k = 0; k < count; ++k) {
      if (stop.load(std::memory_order_relaxed)) continue;
      try {
        row(k);
        const int64_t d = done.fetch_add(1, std::memory_order_relaxed) + 1;
        if (caller) progress.report(double(d) / double(count));
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
