// SPDX-License-Identifier: GPL-3.0-or-later
// The erosion pipeline: validation, fluvial -> hydraulic -> thermal (large
// scale to small), and the maps (terrain_maps.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <omp.h>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "erosion/block_drainage.hpp"
#include "erosion/erosion.hpp"
#include "erosion/erosion_params.hpp"
#include "erosion/landscape_window.hpp"
#include "erosion/sea.hpp"

namespace ft::erosion {
namespace {

void check_rate(const char* name, double v) {
  if (!(v >= 0.0) || !std::isfinite(v)) invalid(std::string(name) + " must be a finite number >= 0, got " + format_number(v));
}

void check_map(const std::string& name, const MapInput& m) {
  if (!m.values) return;
  for (const auto& [side, n] : {std::pair{"_width", m.width}, std::pair{"_height", m.height}})
    if (n < 2 || n > kMaxMapSide)
      invalid(name + side + " must be in 2.." + std::to_string(kMaxMapSide) +
              " (bilinear resampling needs two samples a side), got " + std::to_string(n));
  const size_t n = size_t(m.width) * size_t(m.height);
  for (size_t i = 0; i < n; ++i)
    if (!(m.values[i] >= 0.0f && m.values[i] <= 1.0f))  // NaN fails both
      invalid(name + "'s values must be in [0, 1]; sample " + std::to_string(i % size_t(m.width)) + ", " +
              std::to_string(i / size_t(m.width)) + " is " + format_number(m.values[i]) +
              " (normalise an image to 0..1)");
}

// 6 significant digits: a float sample and the limit as people write them
// (1e+38, not 9.9999996802856925e+37).
std::string short_number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%g", v);
  return s;
}

Heightfield like(const Heightfield& hf) {
  Heightfield out(hf.width(), hf.height());
  out.set_world_size(hf.world_size());
  return out;
}

}  // namespace

D8Grid grid_of(const Heightfield& hf, bool periodic) {
  D8Grid g;
  g.width = hf.width();
  g.height = hf.height();
  g.periodic = periodic;
  g.spacing = hf.world_size() > 0 ? hf.world_size() / (hf.width() - 1) : 1.0;
  return g;
}

void validate(const ErosionConfig& c, const Heightfield& hf) {
  if (hf.width() < 3 || hf.height() < 3)
    invalid("erosion needs a terrain of at least 3 x 3 samples, got " + std::to_string(hf.width()) + " x " +
            std::to_string(hf.height()));
  for (size_t i = 0; i < hf.size(); ++i)
    if (!(std::fabs(hf.data()[i]) <= kMaxErosionHeight))  // NaN too
      invalid("terrain height at sample " + std::to_string(i % hf.width()) + ", " + std::to_string(i / hf.width()) +
              " is " + short_number(hf.data()[i]) + ": erosion needs finite heights within +-" +
              short_number(kMaxErosionHeight) + " world units (a relief up to " + short_number(2 * kMaxErosionHeight) +
              "; beyond, its float arithmetic overflows)");
  validate_settings(c);
}

void validate_settings(const ErosionConfig& c) {
  // Every range is the table's (erosion_params.cpp); only the settings the
  // C struct does not carry, and the cross-field limits, are checked here.
  const ft_erosion_params p = to_c(c);
  check_ranges(erosion_param_table(), &p);
  check_range("hydraulic.min_tilt", c.hydraulic.min_tilt, 0.0, 1.0);
  check_rate("hydraulic.max_erosion", c.hydraulic.max_erosion);
  const auto& f = c.fluvial;
  if (f.uplift * f.dt * f.steps > kMaxErosionHeight)
    invalid("uplift x fluvial_dt x fluvial_steps (the total uplift) must be <= " +
            short_number(kMaxErosionHeight) + " world units, got " + format_number(f.uplift * f.dt * f.steps));
  check_map("erosion_mask", c.erosion_mask);
  check_map("rain_map", c.rain_map);
  resolve_threads(c.threads);
}

ThreadScope::ThreadScope(int requested) : saved_(omp_get_max_threads()) { omp_set_num_threads(resolve_threads(requested)); }
ThreadScope::~ThreadScope() { omp_set_num_threads(saved_); }

bool erodes_by_windows(const ErosionConfig& c) {
  return c.fluvial.steps == 0 && c.hydraulic.iterations == 0 && c.thermal.iterations == 0;
}

void erode_window(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, int64_t x0, int64_t y0,
                  int32_t w, int32_t h, float* before, float* after) {
  if (!erodes_by_windows(c))
    invalid("windows of an eroded terrain take the landscape model alone (fluvial_steps, hydraulic_iterations "
            "and thermal_iterations 0: each of those passes reads the whole grid)");
  landscape_window(m, src, c, x0, y0, w, h, after, c.progress);
  src.read(x0, y0, w, h, before);
  if (std::isnan(m.sea_level)) return;
  // erode()'s last rule: the sea stays, and no land is cut below it.
  const float floor = float(m.sea_level);
  for (size_t i = 0; i < size_t(w) * size_t(h); ++i)
    after[i] = in_sea(before[i], m.sea_level) ? before[i] : std::max(after[i], floor);
}

Heightfield erode(const Heightfield& in, const ErosionConfig& c, ErosionMaps* maps, MassBudget* budget) {
  validate(c, in);
  const ThreadScope threads(c.threads);

  D8Grid g = grid_of(in, c.periodic);
  // The sea of the input, every cell at or below its level (an inland sea
  // of the landform too, or sediment fills it into a plain): base levels
  // for the whole run.
  const double level = sea_height(c.sea, c.sea_level, c.sea_fraction, in);
  std::vector<uint8_t> sea;
  if (c.sea != Sea::kNone) {
    sea.resize(in.size());
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(in.size()); ++i) sea[i] = in_sea(in.data()[i], level);
    g.sea = sea.data();
  }
  // Fresh grids are set by the team (their pages are zeroed by the kernel
  // on first touch: serial work otherwise).
  const int64_t cells = int64_t(in.size());
  Heightfield out = like(in);
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < cells; ++i) out.data()[i] = in.data()[i];
  // The expert rain and scree passes move material cell to cell: what they
  // lay on the sea floor, the sea carries away. And no land is cut below
  // the sea, its base level (the model's change, resampled from its coarser
  // grid, and creep on the detail could take a coastal cell a little below).
  auto keep_sea = [&] {
    if (!g.sea) return;
    const float floor = float(level);
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(in.size()); ++i)
      out.data()[i] = sea[i] ? in.data()[i] : std::max(out.data()[i], floor);
  };
  // Progress: the processes share the bar by their cost, in grid passes
  // (a fluvial step or a model step costs about 20 hydraulic passes; the
  // maps about 8 model steps: at 4097^2 with Land, 4.9 s against the
  // model's 15 s).
  const double model = c.model.strength * c.model.duration > 0 ? 20.0 * 24 : 0.0;
  const double maps_cost = maps ? 20.0 * 8 : 0.0;
  const double total =
      model + double(c.fluvial.steps) * 20 + c.hydraulic.iterations + c.thermal.iterations + maps_cost + 1;
  double done = 0;
  auto run = [&](double weight, auto&& body) {
    const ProgressPart part(c.progress, done / total, weight / total);
    body(part.progress());
    done += weight;
  };
  if (maps) {
    maps->drainage_area = like(in);
    maps->slope = like(in);
    maps->curvature = like(in);
    maps->water_depth = like(in);
    maps->eroded = like(in);
    maps->deposited = like(in);
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < cells; ++i) maps->water_depth.data()[i] = 0.0f;  // without a hydraulic pass
  }
  // What the fluvial run lifted each cell (the maps' depths are against it).
  std::vector<float> lifted;
  if (maps && c.fluvial.steps > 0) {
    lifted = uplift_per_step(g, in.data(), c.fluvial);
    for (float& v : lifted) v *= float(c.fluvial.steps);
  }
  LandscapeModel lm;
  lm.g = g, lm.g.sea = nullptr, lm.sea_level = level;  // (the model's, when it runs)
  if (model > 0) run(model, [&](const Progress& p) { landscape(g, in.data(), out.data(), c, level, budget, p, &lm); });
  if (c.fluvial.steps > 0)
    run(c.fluvial.steps * 20.0, [&](const Progress& p) { fluvial(g, out.data(), c.fluvial, p); });
  if (c.hydraulic.iterations > 0)
    run(c.hydraulic.iterations, [&](const Progress& p) {
      hydraulic(g, out.data(), c.hydraulic, maps ? maps->water_depth.data() : nullptr, budget, p);
    });
  if (c.thermal.iterations > 0)
    run(c.thermal.iterations, [&](const Progress& p) { thermal(g, out.data(), c.thermal, p); });
  keep_sea();
  if (maps)
    run(maps_cost, [&](const Progress& p) {
      // A large terrain drains by pieces, as its windows do (block_drainage.hpp).
      if (!drains_by_blocks(g)) return erosion_maps(g, in.data(), out.data(), lifted, *maps, p);
      const CoarseFlow coarse = coarse_flow(lm, ArraySource(g, out.data()), g.spacing);
      erosion_maps(g, in.data(), out.data(), lifted, *maps, p, &coarse);
    });
  c.progress.report(1.0);
  return out;
}

}  // namespace ft::erosion
