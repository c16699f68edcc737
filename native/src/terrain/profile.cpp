#include "terrain/profile.hpp"

#include <cmath>
#include <vector>

#include "core/rng.hpp"

namespace ft {

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
  std::vector<float> g;
  for (int s = first_step; s <= c.levels; ++s) {
    const int64_t big = n >> (s - 1), half = big / 2, count = n / big;
    const float delta = float(std::pow(2.0, -s * c.hurst) * c.sigma * rho);
    g.resize(size_t(count));
    // Row 1 keeps these apart from the two end-point draws in row 0.
    gaussian_fill(c.seed, Counter{1, uint32_t(s), Stream::kProfile}, 0, size_t(count), g.data());
    for (int64_t i = 0, m = half; i < count; ++i, m += big)
      x[m] = 0.5f * (x[m - half] + x[m + half]) + delta * g[size_t(i)];
    c.progress.report(double(s) / c.levels);
  }
}

}  // namespace ft
