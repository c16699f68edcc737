// SPDX-License-Identifier: GPL-3.0-or-later
// fBm octave noise (noise/fbm.hpp) as a row of the method table
// (terrain_methods.hpp).
#include "core/error.hpp"
#include "noise/fbm.hpp"
#include "terrain/terrain_methods.hpp"

namespace ft::terrain {
namespace {

const noise::FbmConfig& config_of(const std::any& c) { return std::any_cast<const noise::FbmConfig&>(c); }

// The noise layer's enums carry the ABI's values, so basis and variant pass through.
static_assert(int(noise::kBasisValue) == FT_BASIS_VALUE && int(noise::kBasisGradient) == FT_BASIS_GRADIENT &&
              int(noise::kBasisSimplex) == FT_BASIS_SIMPLEX && int(noise::kBasisCellularF1) == FT_BASIS_CELLULAR_F1 &&
              int(noise::kBasisCellularF2F1) == FT_BASIS_CELLULAR_F2F1);
static_assert(int(noise::kFbmStandard) == FT_FBM_STANDARD && int(noise::kFbmRidged) == FT_FBM_RIDGED &&
              int(noise::kFbmHybrid) == FT_FBM_HYBRID && int(noise::kFbmHetero) == FT_FBM_HETERO);

}  // namespace

std::any fbm_configure(const ft_terrain_params& p) {
  noise::FbmConfig c;
  c.width = p.width, c.height = p.height, c.octaves = p.octaves, c.lacunarity = p.lacunarity;
  c.gain = p.gain, c.hurst = p.hurst, c.basis = p.basis, c.variant = p.variant;
  c.frequency = p.frequency, c.offset = p.offset, c.rotation = p.octave_rotation, c.warp = p.warp;
  c.sigma = p.sigma, c.periodic = p.periodic != 0, c.seed = p.seed, c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

void fbm_validate(const std::any& config, int64_t max_side) { noise::validate_fbm(config_of(config), max_side); }

// fbm_height_bound: the octave recurrences at the noise's bound.
void fbm_check_heights(const std::any& config, const ft_terrain_params& p) {
  double unscaled = 0;
  const double per_sigma = noise::fbm_height_bound(config_of(config), &unscaled);
  if (!(unscaled <= kMaxFloatHeight))
    invalid("the fbm octave sum could reach " + format_number(unscaled) + " with offset " + format_number(p.offset) +
            " and " + std::to_string(p.octaves) + " octaves, beyond the float range; use a smaller |offset| or "
            "fewer octaves");
  check_height_bound("sigma", p.sigma, per_sigma);
}

Heightfield fbm_generate(const std::any& config) { return noise::fbm(config_of(config)); }

Heightfield fbm_window(const std::any& config, const Window& w, int) {
  return noise::fbm_window(config_of(config), w.x0, w.y0, w.width, w.height);
}

}  // namespace ft::terrain
