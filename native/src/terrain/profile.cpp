// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/profile.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/rng.hpp"

namespace ft::terrain {

void midpoint_profile(const ProfileConfig& c, float* x) {
  const int64_t n = int64_t(1) << c.levels;
  int first_step = 1;
  if (c.reference) {
    const int64_t step = n >> c.ref_levels;
    for (int64_t i = 0; i <= (int64_t(1) << c.ref_levels); ++i) x[i * step] = c.reference[i];
    first_step = c.ref_levels + 1;
  } else {
    float g[2];
    gaussian_fill(c.seed, Counter{0, 0, Stream::kProfile}, 0, 2, g);
    x[0] = 0.0f;
    x[n] = float(c.sigma) * g[0];
  }
  const double rho = std::sqrt(1.0 - std::pow(2.0, 2.0 * c.hurst - 2.0));
  // Midpoints are drawn and placed in bands of kBand, with a progress report
  // after each: the last of 28 steps is 1.3e8 midpoints, and a band-sized
  // scratch replaces one of 512 MiB. gaussian_fill is addressed by index, so
  // banding gives the same numbers.
  constexpr int64_t kBand = int64_t(1) << 20;
  std::vector<float> g(size_t(std::min<int64_t>(n / 2, kBand)));
  const double total = double(n - (int64_t(1) << (first_step - 1)));  // midpoints to place
  double done = 0;
  for (int s = first_step; s <= c.levels; ++s) {
    const int64_t big = n >> (s - 1), half = big / 2, count = n / big;
    const float delta = float(std::pow(2.0, -s * c.hurst) * c.sigma * rho);
    for (int64_t i0 = 0; i0 < count; i0 += kBand) {
      const int64_t i1 = std::min(count, i0 + kBand);
      // Row 1 keeps these apart from the two end-point draws in row 0.
      gaussian_fill(c.seed, Counter{1, uint32_t(s), Stream::kProfile}, uint64_t(i0), size_t(i1 - i0), g.data());
      for (int64_t i = i0, m = half + i0 * big; i < i1; ++i, m += big)
        x[m] = 0.5f * (x[m - half] + x[m + half]) + delta * g[size_t(i - i0)];
      done += double(i1 - i0);
      c.progress.report(std::min(1.0, done / total));
    }
  }
  c.progress.report(1.0);
}

}  // namespace ft::terrain
