// SPDX-License-Identifier: GPL-3.0-or-later
// The Mandelbrot set's escape time (mandelbrot.hpp) as a row of the method
// table (terrain_methods.hpp).
#include "terrain/mandelbrot.hpp"
#include "terrain/terrain_methods.hpp"

namespace ft::terrain {
namespace {

const MandelbrotConfig& config_of(const std::any& c) { return std::any_cast<const MandelbrotConfig&>(c); }

}  // namespace

std::any mandelbrot_configure(const ft_terrain_params& p) {
  MandelbrotConfig c;
  c.width = p.width, c.height = p.height, c.center_x = p.center_x, c.center_y = p.center_y;
  c.zoom = p.zoom, c.iterations = p.iterations, c.sigma = p.sigma, c.threads = p.threads;
  c.supersample = p.supersample;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

void mandelbrot_validate(const std::any& config, int64_t max_side) { validate_mandelbrot(config_of(config), max_side); }

// h = sigma (1 - (1 + s)^(-1/2)) lies in [0, sigma).
void mandelbrot_check_heights(const std::any& config, const ft_terrain_params&) {
  check_height_bound("sigma", config_of(config).sigma, 1.0);
}

Heightfield mandelbrot_generate(const std::any& config) { return mandelbrot(config_of(config)); }

Heightfield mandelbrot_window(const std::any& config, const Window& w, int) {
  return mandelbrot_window(config_of(config), w.x0, w.y0, w.width, w.height);
}

void mandelbrot_height_range(const ft_terrain_params& p, double* lo, double* hi) { *lo = 0.0, *hi = p.sigma; }

}  // namespace ft::terrain
