// SPDX-License-Identifier: GPL-3.0-or-later
// Spectral synthesis (spectral_synthesis.hpp) as a row of the method table
// (terrain_methods.hpp). One global FFT: no windows.
#include <cmath>

#include "terrain/spectral_synthesis.hpp"
#include "terrain/terrain_methods.hpp"

namespace ft::terrain {

std::any spectral_configure(const ft_terrain_params& p) {
  SpectralConfig c;
  c.width = p.width, c.height = p.height, c.hurst = p.hurst, c.sigma = p.sigma, c.seed = p.seed;
  c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

// |sum c_k| <= sqrt(N) (sum |c_k|^2)^(1/2) over the N = W H coefficients
// (Cauchy-Schwarz), whose power is sigma^2 times at most
// spectral_power_ratio_bound (the waves finer than sigma's reference band
// add to it) with |g| <= 6 on both parts: S = 6 sqrt(2 W H ratio).
void spectral_check_heights(const std::any& config, const ft_terrain_params&) {
  const SpectralConfig& c = std::any_cast<const SpectralConfig&>(config);
  const double ratio = spectral_power_ratio_bound(c.width, c.height, c.hurst);
  check_height_bound("sigma", c.sigma, kMaxGaussian * std::sqrt(2.0 * c.width * c.height * ratio));
}

Heightfield spectral_generate(const std::any& config) {
  return spectral_synthesis(std::any_cast<const SpectralConfig&>(config));
}

}  // namespace ft::terrain
