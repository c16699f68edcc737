// SPDX-License-Identifier: GPL-3.0-or-later
// Saupe's InterpolatedFM (interpolated.hpp) as a row of the method table
// (terrain_methods.hpp).
#include <algorithm>
#include <cmath>

#include "terrain/interpolated.hpp"
#include "terrain/terrain_methods.hpp"

namespace ft::terrain {
namespace {

const InterpolatedConfig& config_of(const std::any& c) { return std::any_cast<const InterpolatedConfig&>(c); }

}  // namespace

std::any interpolated_configure(const ft_terrain_params& p) {
  InterpolatedConfig c;
  c.width = p.width, c.height = p.height;
  c.lacunarity = p.lacunarity, c.hurst = p.hurst, c.sigma = p.sigma;
  c.seed = p.seed, c.periodic = p.periodic != 0, c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

void interpolated_validate(const std::any& config, int64_t) {
  check_interpolated_lacunarity(config_of(config).lacunarity);
}

// The corners plus one Gaussian per cycle, each at most sigma.
void interpolated_check_heights(const std::any& config, const ft_terrain_params&) {
  const InterpolatedConfig& c = config_of(config);
  const double d0 = std::max(c.width, c.height);
  check_height_bound("sigma", c.sigma, kMaxGaussian * (2 + std::ceil(std::log(d0) / std::log(c.lacunarity))));
}

Heightfield interpolated_generate(const std::any& config) { return interpolated_fm(config_of(config)); }

Heightfield interpolated_window(const std::any& config, const Window& w, int) {
  return interpolated_window(config_of(config), w.x0, w.y0, w.width, w.height);
}

}  // namespace ft::terrain
