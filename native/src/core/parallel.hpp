// Thread-count handling. Results never depend on the thread count: random
// numbers are keyed by position (core/rng.hpp), not drawn in order.
#pragma once

#include <omp.h>

#include "core/error.hpp"

namespace ft {

// Resolves a user thread count (0 = all cores) to what OpenMP should use.
inline int resolve_threads(int requested) {
  check_int_range("threads", requested, 0, 1024);
  return requested == 0 ? omp_get_max_threads() : requested;
}

}  // namespace ft
