// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/heightfield.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"

namespace ft {

Heightfield::Heightfield(int32_t width, int32_t height) : width_(width), height_(height) {
  check_int_range("width", width, 1, 1 << 20);
  check_int_range("height", height, 1, 1 << 20);
  check_allocation(checked_bytes(uint64_t(width), uint64_t(height), sizeof(float)),
                   "a " + std::to_string(width) + " x " + std::to_string(height) + " heightfield");
  samples_ = Buffer<float>(size_t(width) * size_t(height));
}

HeightStats Heightfield::stats() const {
  HeightStats s;
  const size_t n = size();
  if (n == 0) return s;
  double lo = samples_[0], hi = samples_[0];
  // At most the cores other processes leave free (core/parallel.hpp): the
  // CLI and Blender call this outside any stage that sets its threads, and
  // on a busy machine a full team spin-waits at each of its barriers.
  const int team = resolve_threads(0);
#pragma omp parallel for num_threads(team) reduction(min : lo) reduction(max : hi)
  for (size_t i = 0; i < n; ++i) {
    const double v = samples_[i];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // The sums in an order of their own: the same bits however many threads
  // the load leaves.
  const float* z = samples_.data();
  const double mean = ordered_sum(int64_t(n), team, [z](int64_t i) { return double(z[i]); }) / double(n);
  const double ss = ordered_sum(int64_t(n), team, [z, mean](int64_t i) {
    const double d = z[i] - mean;
    return d * d;
  });
  s.min = lo;
  s.max = hi;
  s.mean = mean;
  s.std = std::sqrt(ss / double(n));
  return s;
}

}  // namespace ft
