// SPDX-License-Identifier: GPL-3.0-or-later
// Row-parallel loops that report progress and can be cancelled: the rows go
// to threads one at a time, the calling thread (OpenMP's thread 0) reports.
#pragma once

#include <cstdint>
#include <functional>

#include "core/progress.hpp"

namespace ft {

// Runs row(k) for k in 0..count-1 in parallel on up to `threads` threads
// (0: all cores; see resolve_threads); each must depend on k alone and
// write only its own outputs, so the result is the same on any thread
// count. Progress (k rows done of count) is reported by the calling thread
// after its rows, at most about 128 times, then 1; a cancellation (or an exception from a
// row) stops the rest and is rethrown.
void for_rows(int64_t count, int threads, const Progress& progress, const std::function<void(int64_t)>& row);

}  // namespace ft
