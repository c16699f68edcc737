// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/height_range.hpp"

#include <algorithm>
#include <cmath>

#include "terrain/landform.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_method.hpp"

namespace ft::tiles {
namespace {

constexpr int kCoarseLevels = 12;     // the bound's coarse pass: at most 4097^2 samples
constexpr double kGaussianBound = 5.9;  // |g| <= sqrt(50 ln 2) = 5.888 (see the header)

// Methods whose coarser stages keep their samples (plain midpoint): the
// coarse pass plus a margin for the finer displacements bounds the heights.
bool has_midpoint_bound(const ft_terrain_params& p) {
  if (!terrain::terrain_method(p.method).stages_keep_samples) return false;
  // The margin bounds the raw method's finer displacements; the landforms
  // (levelling, falloff, sea) reshape them, so such terrains take the exact pass.
  if (terrain::has_landforms(p)) return false;
  if (p.reference == nullptr) return true;
  const int m = terrain::dyadic_levels(p.reference_size);
  return p.reference_scale == FT_REFSCALE_SIGMA && m >= 1 && m <= std::min(p.levels, kCoarseLevels);
}

}  // namespace

double midpoint_bound_margin(int levels, int m, double hurst, double sigma) {
  double sum = 0.0;
  for (int k = 2 * m + 1; k <= 2 * levels; ++k) sum += sigma * std::pow(2.0, -0.5 * k * hurst);
  return kGaussianBound * sum;
}

HeightRange tileset_height_range(const TileTerrain& t, const TileSpec& spec, const std::string& dir) {
  const ft_terrain_params& p = t.terrain;
  const TileGrid& grid = spec.grid;
  HeightRange r;
  if (t.erodes()) {  // erosion moves every height: the exact pass, keeping what it builds
    r = {INFINITY, -INFINITY, "exact"};
    for (int32_t row = 0; row < grid.rows(); ++row)
      for (int32_t col = 0; col < grid.columns(); ++col) {
        const HeightRange h = tile_height_range(t, spec, dir, col, row);
        r.min = std::min(r.min, h.min);
        r.max = std::max(r.max, h.max);
      }
    return r;
  }
  if (const auto formula = terrain::terrain_method(p.method).height_range) {
    r.how = "formula";
    formula(p, &r.min, &r.max);
    return r;
  }
  if (has_midpoint_bound(p)) {
    const int m = std::min(p.levels, kCoarseLevels), lod = p.levels - m;
    const int32_t side = int32_t((int64_t(1) << m) + 1);
    const HeightStats s = terrain::generate_terrain_window(p, lod, 0, 0, side, side).stats();
    const double margin = midpoint_bound_margin(p.levels, m, p.hurst, p.sigma);
    const double slack = 1e-5 * (std::max(std::abs(s.min), std::abs(s.max)) + margin);
    r = {s.min - margin - (lod ? slack : 0.0), s.max + margin + (lod ? slack : 0.0), lod ? "bound" : "exact"};
    return r;
  }
  r = {INFINITY, -INFINITY, "exact"};
  for (int32_t row = 0; row < grid.rows(); ++row)
    for (int32_t col = 0; col < grid.columns(); ++col) {
      const HeightRange t = tile_height_range(p, grid, col, row);
      r.min = std::min(r.min, t.min);
      r.max = std::max(r.max, t.max);
    }
  return r;
}

HeightRange tileset_height_range(const ft_terrain_params& p, const TileGrid& grid) {
  TileSpec spec;
  spec.grid = grid;
  return tileset_height_range(TileTerrain::of(p), spec, "");
}

bool needs_exact_pass(const ft_terrain_params& p) {
  return !terrain::terrain_method(p.method).height_range && !has_midpoint_bound(p);
}

bool needs_exact_pass(const TileTerrain& t) { return t.erodes() || needs_exact_pass(t.terrain); }

HeightRange tile_height_range(const TileTerrain& t, const TileSpec& spec, const std::string& dir, int32_t col,
                              int32_t row) {
  if (!t.erodes()) return tile_height_range(t.terrain, spec.grid, col, row);
  const auto [lo, hi] = build_pending_tile(t, spec, dir, col, row);
  return {lo, hi, "exact"};
}

HeightRange tile_height_range(const ft_terrain_params& p, const TileGrid& grid, int32_t col, int32_t row) {
  grid.check_tile(col, row);
  const terrain::Window w = grid.window(col, row);
  const HeightStats s = terrain::generate_terrain_window(p, 0, w.x0, w.y0, w.width, w.height).stats();
  return {s.min, s.max, "exact"};
}

}  // namespace ft::tiles
