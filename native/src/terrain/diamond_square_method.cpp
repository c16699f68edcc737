// SPDX-License-Identifier: GPL-3.0-or-later
// Midpoint displacement and successive random additions as rows of the
// method table (terrain_methods.hpp): Voss's diamond-square on
// (2^levels + 1)^2 grids, refining an optional reference grid.
#include <algorithm>
#include <cmath>

#include "core/memory.hpp"
#include "terrain/diamond_square.hpp"
#include "terrain/terrain_methods.hpp"

namespace ft::terrain {
namespace {

const DiamondSquareConfig& config_of(const std::any& c) { return std::any_cast<const DiamondSquareConfig&>(c); }

}  // namespace

std::any diamond_square_configure(const ft_terrain_params& p) {
  DiamondSquareConfig c;
  c.levels = p.levels;
  c.hurst = p.hurst;
  c.seed = p.seed;
  c.periodic = p.periodic != 0;
  c.additions = p.method == FT_TERRAIN_ADDITIONS;
  c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  set_reference(c, p, size_t(p.reference_size) * size_t(p.reference_size));
  return c;
}

// The corners, then at most 4 displacements per level (its creation, and the
// additions of the square and diamond steps), each at most sigma (the
// refinement's scale with a reference): S = 6 (1 + 4 levels) (Voss 1985),
// above the largest |reference value|.
void diamond_square_check_heights(const std::any& config, const ft_terrain_params& p) {
  const DiamondSquareConfig& c = config_of(config);
  const double per_sigma = kMaxGaussian * (1 + 4.0 * p.levels);
  if (!p.reference) return check_height_bound("sigma", c.sigma, per_sigma);
  const size_t n = size_t(p.reference_size) * size_t(p.reference_size);
  double top = 0;
  for (size_t i = 0; i < n; ++i) top = std::max(top, double(std::fabs(p.reference[i])));
  check_height_bound(p.reference_scale == FT_REFSCALE_SIGMA ? "sigma" : "the reference scale", c.sigma, per_sigma,
                     top);
}

Heightfield diamond_square_generate(const std::any& config) { return diamond_square(config_of(config)); }

Heightfield diamond_square_window(const std::any& config, const Window& w, int lod) {
  return diamond_square_window(config_of(config), w, lod);
}

// Plain midpoint writes its last stage straight into the window and
// alternates two arrays for the stages before it (a quarter and a sixteenth
// of it, halo included; bounded here by two quarters).
uint64_t midpoint_window_work_bytes(int, int32_t w, int32_t h) {
  return checked_bytes(uint64_t(w) / 2 + 16, uint64_t(h) / 2 + 16, sizeof(float) * 2);
}

// Additions hold the last stage's array (the window grown by its halo) and
// the stage before it; at lod > 0 they refine the footprint.
uint64_t additions_window_work_bytes(int lod, int32_t w, int32_t h) {
  const uint64_t k = uint64_t(1) << lod;
  const uint64_t fw = (uint64_t(w) - 1) * k + 1 + 16, fh = (uint64_t(h) - 1) * k + 1 + 16;
  return checked_bytes(fw, fh, sizeof(float) * (k > 1 ? 3 : 2));
}

}  // namespace ft::terrain
