// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/planet.hpp"

#include <algorithm>
#include <numbers>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "planet/cube_sampler.hpp"

namespace ft::planet {

void validate_planet(const PlanetConfig& c) {
  check_int_range("method", c.method, kMethodFbm, kMethodMidpoint);
  if (!(c.radius > 0.0) || !std::isfinite(c.radius) || c.radius > 1e12)
    invalid("radius must be in (0, 1e12] metres (the Earth's is 6371000), got " + format_number(c.radius));
  noise::validate_fbm3(c.fbm);
  if (!(c.fbm.sigma <= 1e12))
    invalid("sigma must be in (0, 1e12] metres, got " + format_number(c.fbm.sigma));
  // Heights travel as float32: their bound must stay far inside its range.
  const double bound = noise::fbm3_height_bound(c.fbm) * c.fbm.sigma;
  if (!(bound < 1e30))
    invalid("the heights could reach " + format_number(bound) + " metres, beyond float range; lower sigma, "
            "offset or octaves");
  check_int_range("sea", c.sea, kSeaNone, kSeaFraction);
  if (c.sea == kSeaHeight) {
    if (!std::isfinite(c.sea_level) || std::fabs(c.sea_level) > 1e30)
      invalid("sea_level must be a finite height within +-1e30 metres, got " + format_number(c.sea_level));
  }
  if (c.sea == kSeaFraction && !(c.sea_fraction >= 0.0 && c.sea_fraction < 1.0))
    invalid("sea_fraction must be in [0, 1), got " + format_number(c.sea_fraction));
  check_int_range("threads", c.threads, 0, 1024);
}

std::array<double, 3> fibonacci_point(int64_t i, int64_t n) {
  // z uniform in (-1, 1) (equal areas), longitude turned by the golden angle.
  const double z = 1.0 - (2.0 * double(i) + 1.0) / double(n);
  const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = double(i) * (std::numbers::pi * (3.0 - std::sqrt(5.0)));
  return {r * std::cos(phi), r * std::sin(phi), z};
}

Planet::Planet(const PlanetConfig& c) : config_(c), fbm_((validate_planet(c), c.fbm)) {
  if (c.sea == kSeaHeight) sea_ = c.sea_level;
  if (c.sea == kSeaFraction) {
    // The quantile over equal-area points: the same level for every layout
    // and patch, whatever part of the planet it covers.
    // A midpoint planet's are interpolated from its level-8 cube-sphere
    // (spacing 0.2 to 0.45 degrees), whichever level is then sampled.
    const int64_t n = kSeaQuantilePoints;
    Directions d{size_t(n)};
    for (int64_t i = 0; i < n; ++i) d.set(size_t(i), fibonacci_point(i, n));
    std::vector<float> h(n);
    if (midpoint()) {
      const CubeSampler sampler(midpoint_config(), kSeaQuantileLevel, c.threads, Progress());
      for (int64_t i = 0; i < n; ++i) h[size_t(i)] = sampler.height(d.x[size_t(i)], d.y[size_t(i)], d.z[size_t(i)]);
    } else {
      fbm_.evaluate(n, d.x.data(), d.y.data(), d.z.data(), h.data());
    }
    const size_t k = std::min<size_t>(size_t(n) - 1, size_t(c.sea_fraction * double(n)));
    std::nth_element(h.begin(), h.begin() + std::ptrdiff_t(k), h.end());
    sea_ = c.sea_fraction == 0.0 ? double(*std::min_element(h.begin(), h.end())) : double(h[k]);
  }
}

void Planet::heights(int64_t n, const double* x, const double* y, const double* z, float* out) const {
  if (midpoint())
    invalid("a midpoint planet's heights are its cube-sphere samples, not a function of any point: use "
            "ft_planet_face (a face or patch at a level), or the equirect and icosphere layouts, which interpolate "
            "them");
  fbm_.evaluate(n, x, y, z, out);
  raise_to_sea(n, out);
}

void Planet::raise_to_sea(int64_t n, float* out) const {
  if (!std::isnan(sea_)) {
    const float s = float(sea_);
    for (int64_t i = 0; i < n; ++i) out[i] = out[i] < s ? s : out[i];
  }
}

float Planet::height(double x, double y, double z) const {
  float out;
  heights(1, &x, &y, &z, &out);
  return out;
}

void fill_rows(int32_t w, int32_t h, int threads, const Progress& progress,
               const std::function<void(int32_t, float*)>& row, float* data) {
  for_rows(h, threads, progress, [&](int64_t y) { row(int32_t(y), data + size_t(y) * size_t(w)); });
}

}  // namespace ft::planet
