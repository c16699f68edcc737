// SPDX-License-Identifier: GPL-3.0-or-later
#include "refine/dem_refine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "terrain/terrain.hpp"

namespace ft::refine {
namespace {

// Counts of nodata samples in every rectangle, by a summed-area table.
class HoleCounter {
 public:
  explicit HoleCounter(const Heightfield& dem) : w_(dem.width() + 1), sum_(size_t(w_) * (dem.height() + 1), 0) {
    for (int32_t y = 0; y < dem.height(); ++y)
      for (int32_t x = 0; x < dem.width(); ++x)
        at(x + 1, y + 1) = at(x, y + 1) + at(x + 1, y) - at(x, y) + (std::isfinite(dem.at(x, y)) ? 0 : 1);
  }
  int64_t holes(int x, int y, int side) const {
    return at(x + side, y + side) - at(x, y + side) - at(x + side, y) + at(x, y);
  }

 private:
  int64_t& at(int x, int y) { return sum_[size_t(y) * w_ + x]; }
  int64_t at(int x, int y) const { return sum_[size_t(y) * w_ + x]; }
  int w_;
  std::vector<int64_t> sum_;
};

// The window of side `side` without holes nearest the DEM's centre; false
// when there is none.
bool find_window(const Heightfield& dem, const HoleCounter& holes, int side, int& wx, int& wy) {
  const double cx = (dem.width() - side) * 0.5, cy = (dem.height() - side) * 0.5;
  double best = std::numeric_limits<double>::infinity();
  for (int y = 0; y + side <= dem.height(); ++y)
    for (int x = 0; x + side <= dem.width(); ++x) {
      const double d = (x - cx) * (x - cx) + (y - cy) * (y - cy);
      if (d < best && holes.holes(x, y, side) == 0) best = d, wx = x, wy = y;
    }
  return std::isfinite(best);
}

void place_window(const Heightfield& dem, const DemRefineConfig& c, DemRefineResult& r) {
  const HoleCounter holes(dem);
  const int most = std::min(dem.width(), dem.height());
  if (c.window_side != 0) {
    if (terrain::dyadic_levels(c.window_side) < 1 || c.window_side > most)
      invalid("window side must be 2^m + 1 (3, 5, 9, 17, 33, ...) and at most " + std::to_string(most) +
              " (the DEM is " + std::to_string(dem.width()) + " x " + std::to_string(dem.height()) + "), got " +
              std::to_string(c.window_side));
    r.window_side = c.window_side;
  } else {
    // The largest dyadic side that fits somewhere without nodata.
    int side = 3;
    while (2 * side - 1 <= most) side = 2 * side - 1;
    for (; side >= 3; side = (side + 1) / 2) {
      int x = 0, y = 0;
      if (c.window_x >= 0 && c.window_y >= 0) {
        if (c.window_x + side <= dem.width() && c.window_y + side <= dem.height() &&
            holes.holes(c.window_x, c.window_y, side) == 0)
          break;
      } else if (find_window(dem, holes, side, x, y)) {
        break;
      }
    }
    if (side < 3) invalid("the DEM has no 3 x 3 window without nodata at the place asked for");
    r.window_side = side;
  }
  const int side = r.window_side;
  if (c.window_x >= 0 || c.window_y >= 0) {
    if (c.window_x < 0 || c.window_y < 0 || c.window_x + side > dem.width() || c.window_y + side > dem.height())
      invalid("window at (" + std::to_string(c.window_x) + ", " + std::to_string(c.window_y) + ") of side " +
              std::to_string(side) + " does not fit in the " + std::to_string(dem.width()) + " x " +
              std::to_string(dem.height()) + " DEM");
    r.window_x = c.window_x, r.window_y = c.window_y;
    const int64_t n = holes.holes(r.window_x, r.window_y, side);
    if (n > 0)
      invalid("the window at (" + std::to_string(r.window_x) + ", " + std::to_string(r.window_y) + ") of side " +
              std::to_string(side) + " holds " + std::to_string(n) + " nodata samples");
  } else if (!find_window(dem, holes, side, r.window_x, r.window_y)) {
    invalid("the DEM has no " + std::to_string(side) + " x " + std::to_string(side) + " window without nodata");
  }
}

Heightfield cut(const Heightfield& dem, int x0, int y0, int side) {
  Heightfield w(side, side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) w.at(x, y) = dem.at(x0 + x, y0 + y);
  return w;
}

// Mean squared increment at one sample, rows and columns pooled.
double finest_increment_variance(const Heightfield& w) {
  double sum = 0;
  size_t n = 0;
  for (int y = 0; y < w.height(); ++y)
    for (int x = 0; x < w.width(); ++x) {
      if (x + 1 < w.width()) sum += std::pow(double(w.at(x + 1, y)) - w.at(x, y), 2), ++n;
      if (y + 1 < w.height()) sum += std::pow(double(w.at(x, y + 1)) - w.at(x, y), 2), ++n;
    }
  return sum / double(n);
}

// The georeference of the refined grid: same CRS; the window's origin, with
// pixels 2^K times smaller whose centres fall on the window's centres at
// every 2^K-th node.
GeoReference refined_georef(const GeoReference& g, int wx, int wy, int added) {
  GeoReference r = g;
  if (!g.has_transform) return r;
  const auto& t = g.transform;
  const double f = std::ldexp(1.0, -added);
  // Centre of window pixel (0, 0), in map coordinates.
  const double cx = t[0] + (wx + 0.5) * t[1] + (wy + 0.5) * t[2];
  const double cy = t[3] + (wx + 0.5) * t[4] + (wy + 0.5) * t[5];
  r.transform = {cx - 0.5 * f * (t[1] + t[2]), t[1] * f, t[2] * f, cy - 0.5 * f * (t[4] + t[5]), t[4] * f, t[5] * f};
  return r;
}

}  // namespace

double centre_kriging_factor(double h) { return std::pow(2.0, -h) - 0.25 - std::pow(2.0, h) / 8.0; }

DemRefineResult refine_dem(const Heightfield& dem, const DemRefineConfig& c) {
  // Each field's range is the table's (dem_refine_params.cpp); the checks here
  // relate the parameters to the DEM.
  if (dem.width() < 3 || dem.height() < 3)
    invalid("the DEM is " + std::to_string(dem.width()) + " x " + std::to_string(dem.height()) +
            "; refining needs at least 3 x 3 samples");
  DemRefineResult r;
  place_window(dem, c, r);
  const Heightfield window = cut(dem, r.window_x, r.window_y, r.window_side);
  const int m = terrain::dyadic_levels(r.window_side);
  const int levels = m + c.levels_added;
  if (levels > terrain::kMaxLevels)
    invalid("a window of side " + std::to_string(r.window_side) + " refined by " + std::to_string(c.levels_added) +
            " levels would need " + std::to_string(levels) + " levels; at most " + std::to_string(terrain::kMaxLevels));

  r.v1 = finest_increment_variance(window);
  r.hurst_measured = c.hurst < 0;
  if (r.hurst_measured) {
    if (r.window_side < 9) invalid("measuring H needs a window of at least 9 x 9; give --hurst");
    analysis::HurstOptions o;
    o.method = analysis::HurstMethod::kVariogram;
    o.lag_min = 1;
    o.lag_max = std::max(2, (r.window_side - 1) / 4);
    r.estimate = analysis::estimate_hurst_surface(window, o);
    // H = 1 would add nothing (k(1) = 0); the variogram of a DEM with a trend
    // can slightly exceed it.
    r.hurst = std::clamp(r.estimate.hurst, 0.0, 0.99);
  } else {
    r.hurst = c.hurst;
  }
  r.sigma_measured = !(c.sigma > 0);
  if (r.sigma_measured) {
    if (!(r.v1 > 0)) invalid("the DEM window is flat (no increment at one pixel); give --sigma");
    r.sigma = std::sqrt(r.v1 * centre_kriging_factor(r.hurst)) * std::pow(2.0, m * r.hurst + 0.5 * r.hurst);
  } else {
    r.sigma = c.sigma;
  }

  ft_terrain_params p = terrain::default_terrain_params();
  p.method = c.additions ? FT_TERRAIN_ADDITIONS : FT_TERRAIN_MIDPOINT;
  p.levels = levels;
  p.hurst = r.hurst;
  p.sigma = r.sigma;
  p.seed = c.seed;
  p.threads = c.threads;
  p.reference = window.data();
  p.reference_size = r.window_side;
  p.reference_scale = FT_REFSCALE_SIGMA;
  p.progress = c.progress;
  p.progress_user = c.progress_user;
  p.world_size = dem.world_size() > 0 ? dem.world_size() * (r.window_side - 1) / (dem.width() - 1) : 1.0;
  r.terrain = terrain::generate_terrain(p);
  r.terrain.set_georef(refined_georef(dem.georef(), r.window_x, r.window_y, c.levels_added));
  return r;
}

}  // namespace ft::refine
