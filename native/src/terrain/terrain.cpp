// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/terrain.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "terrain/landform.hpp"
#include "terrain/profile.hpp"
#include "terrain/terrain_methods.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::terrain {

double reference_scale(int mode, double sigma, const float* ref, size_t n) {
  if (mode == FT_REFSCALE_SIGMA) return sigma;
  double sum_abs = 0, sum = 0, sum2 = 0;
  for (size_t i = 0; i < n; ++i) sum_abs += std::fabs(ref[i]), sum += ref[i], sum2 += double(ref[i]) * ref[i];
  const double mean_abs = sum_abs / double(n), mean = sum / double(n);
  const double scale = mode == FT_REFSCALE_MEAN ? mean_abs : std::sqrt(std::max(0.0, sum2 / double(n) - mean * mean));
  if (!(scale > 0))
    invalid(std::string("reference_scale ") + (mode == FT_REFSCALE_MEAN ? "'mean'" : "'std'") +
            " gives 0 for these reference values; use reference_scale 'sigma' with a sigma > 0");
  return scale;
}

void check_height_bound(const std::string& what, double sigma, double per_sigma, double base) {
  const double bound = base + sigma * per_sigma;
  if (bound <= kMaxFloatHeight) return;
  invalid(what + " " + format_number(sigma) + " is too large: heights could reach " + format_number(bound) +
          ", beyond the float range (" + format_number(kMaxFloatHeight) + " with headroom); for these settings it "
          "must be at most " + format_number((kMaxFloatHeight - base) / per_sigma));
}

int dyadic_levels(int64_t size) {
  if (size < 3) return -1;
  const int64_t n = size - 1;
  if ((n & (n - 1)) != 0) return -1;
  int m = 0;
  while ((int64_t(1) << m) < n) ++m;
  return m;
}

std::span<const TerrainMethod> terrain_methods() { return kTerrainMethods; }

const TerrainMethod& terrain_method(int32_t method) {
  if (method < 0 || method >= kTerrainMethodCount)
    invalid("method must be in 0.." + std::to_string(kTerrainMethodCount - 1) + ", got " + std::to_string(method));
  return kTerrainMethods[method];
}

bool tiles_periodically(const ft_terrain_params& p) {
  const Tiling t = terrain_method(p.method).tiling;
  return t == Tiling::kAlways || (t == Tiling::kOnRequest && p.periodic != 0);
}

std::string methods_that(bool (*has)(const TerrainMethod&)) {
  std::vector<std::string> names;
  for (const TerrainMethod& m : kTerrainMethods)
    if (has(m)) {
      std::string name = m.item.name;
      for (char& ch : name) ch = char(std::tolower(static_cast<unsigned char>(ch)));
      names.push_back(name);
    }
  std::string text;
  for (size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  return text;
}

void dyadic_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height) {
  check_int_range("lod", lod, 0, p.levels);
  *width = *height = (int64_t(1) << (p.levels - lod)) + 1;
}

void sized_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height) {
  if (lod != 0)
    invalid("a level of detail (lod " + std::to_string(lod) + ") is defined for " +
            methods_that([](const TerrainMethod& m) { return m.lod; }) +
            " terrains, whose every 2^lod-th sample is a coarser stage; use lod 0 for other methods");
  *width = p.width, *height = p.height;
}

// The rows are the methods in order, and each names its functions. GCC's
// sanitizer builds (-fno-delete-null-pointer-checks) cannot fold a function's
// address against null at compile time; the Release build checks that part.
static_assert([] {
  for (int32_t i = 0; i < kTerrainMethodCount; ++i)
    if (kTerrainMethods[i].item.value != i) return false;
  return true;
}());
#if !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_UNDEFINED__) && !defined(FT_SANITIZE)
static_assert([] {
  for (const TerrainMethod& m : kTerrainMethods) {
    if (!m.configure || !m.check_heights || !m.generate || !m.extent) return false;
    if (!m.window && !m.no_windows) return false;
  }
  return true;
}());
#endif

ft_terrain_params default_terrain_params() { return defaults_of<ft_terrain_params>(terrain_param_table()); }

namespace {

void check_reference(const float* ref, int32_t size, int levels, bool periodic) {
  const int m = dyadic_levels(size);
  if (m < 1 || m > levels)
    invalid("reference_size must be 2^m + 1 with 1 <= m <= levels (" + std::to_string(levels) +
            "), i.e. one of 3, 5, 9, ..., " + std::to_string((1 << levels) + 1) + "; got " +
            std::to_string(size));
  const size_t n = size_t(size) * size_t(size);
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(ref[i]))
      invalid("reference value " + std::to_string(i) + " is " + format_number(ref[i]) + "; all must be finite");
  if (periodic) {
    for (int k = 0; k < size; ++k)
      if (ref[k] != ref[size_t(size - 1) * size + k] || ref[size_t(k) * size] != ref[size_t(k) * size + size - 1])
        invalid("a periodic terrain needs a periodic reference grid: its last row and column must equal its first");
  }
}

// One call's method and its generator's configuration, built once from the
// params after they were checked.
struct MethodCall {
  const TerrainMethod& method;
  std::any config;
};

// The checks of every terrain; `whole` adds the size limits of a terrain
// held in memory, otherwise those of windows (which never hold the whole).
MethodCall validate_terrain(const ft_terrain_params& p, bool whole) {
  check_struct_size(p.struct_size, sizeof(ft_terrain_params), "ft_terrain_params");
  const TerrainMethod& m = terrain_method(p.method);
  // The ranges of every field the method uses come from the table; what
  // follows relates fields to each other. The table's levels and sizes are
  // those of a whole terrain: a window's larger ones are checked here first.
  ft_terrain_params q = p;
  if (!whole) {
    if (m.dyadic) {
      check_int_range("levels", p.levels, 1, kMaxWindowLevels);
      q.levels = std::min(p.levels, kMaxLevels);
    } else {
      check_int_range("width", p.width, 2, kMaxWindowSide);
      check_int_range("height", p.height, 2, kMaxWindowSide);
      q.width = std::min(p.width, 65536), q.height = std::min(p.height, 65536);
    }
  }
  check_ranges(terrain_param_table(), &q);
  const int64_t max_side = whole ? 65536 : kMaxWindowSide;
  if (m.dyadic) {
    const uint64_t side = (uint64_t(1) << p.levels) + 1;
    if (whole)
      check_allocation(checked_bytes(side, side, sizeof(float)),
                       "a terrain of levels " + std::to_string(p.levels) + " (" + std::to_string(side) + " x " +
                           std::to_string(side) + " samples); windows of it (ft_terrain_generate_window) need not fit");
  } else if (whole) {
    check_allocation(checked_bytes(uint64_t(p.width), uint64_t(p.height), sizeof(float)),
                     "a " + std::to_string(p.width) + " x " + std::to_string(p.height) + " terrain");
  }
  if (p.reference && !m.reference)
    invalid("reference points are supported by the " + methods_that([](const TerrainMethod& r) { return r.reference; }) +
            " methods only");
  if (p.reference) check_reference(p.reference, p.reference_size, p.levels, p.periodic != 0);
  MethodCall call{m, m.configure(p)};
  if (m.validate) m.validate(call.config, max_side);
  m.check_heights(call.config, p);
  validate_landforms(p, whole);
  return call;
}

}  // namespace

void validate_terrain_params(const ft_terrain_params& p) { validate_terrain(p, true); }

Heightfield generate_terrain(const ft_terrain_params& p) {
  const MethodCall call = validate_terrain(p, true);
  // Every method records the world size here, in one place: it used to be
  // set by the midpoint branch only, so fbm, spectral and interpolated
  // terrains lost it (and `coastline --world` refused them).
  Heightfield hf = call.method.generate(call.config);
  if (has_landforms(p)) {
    const int w = hf.width(), h = hf.height();
    const Corners corners{hf.at(0, 0), hf.at(w - 1, 0), hf.at(0, h - 1), hf.at(w - 1, h - 1)};
    apply_landforms(p, corners, Placement{0, 0, 1, w, h}, hf, p.threads);
    apply_sea(p, hf);
  }
  hf.set_world_size(p.world_size);
  return hf;
}

namespace {

// The whole terrain's extent at `lod` for windows, with the call's method and configuration.
MethodCall window_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height) {
  MethodCall call = validate_terrain(p, false);
  const TerrainMethod& m = call.method;
  if (!m.window)
    invalid(std::string(m.item.label) + " terrains have no windows: " + m.no_windows + "; generate it whole (up to "
            "65536 x 65536), or use windows of " + methods_that([](const TerrainMethod& r) { return r.window != nullptr; }) +
            " terrains");
  m.extent(p, lod, width, height);
  return call;
}

}  // namespace

void terrain_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height) {
  window_extent(p, lod, width, height);
}

Heightfield generate_terrain_window(const ft_terrain_params& p, int lod, int64_t x0, int64_t y0, int32_t w,
                                    int32_t h) {
  int64_t ew = 0, eh = 0;
  const MethodCall call = window_extent(p, lod, &ew, &eh);
  if (w < 1 || h < 1)
    invalid("a window needs at least 1 x 1 samples, got " + std::to_string(w) + " x " + std::to_string(h));
  if (x0 < 0 || y0 < 0 || x0 > ew - w || y0 > eh - h)
    invalid("the window [" + std::to_string(x0) + ", " + std::to_string(x0 + w) + ") x [" + std::to_string(y0) +
            ", " + std::to_string(y0 + h) + ") lies outside the terrain's " + std::to_string(ew) + " x " +
            std::to_string(eh) + " samples" + (lod ? " at lod " + std::to_string(lod) : std::string()));
  const uint64_t work = call.method.window_work_bytes ? call.method.window_work_bytes(lod, w, h) : 0;
  check_allocation(checked_bytes(uint64_t(w), uint64_t(h), sizeof(float)) + work,
                   "a " + std::to_string(w) + " x " + std::to_string(h) + " window");
  Heightfield hf = call.method.window(call.config, Window{x0, y0, w, h}, lod);
  if (has_landforms(p)) {
    // The levelling needs the whole terrain's corners: four 1 x 1 windows
    // (for midpoint a chain of tiny halos, for the others one sample each).
    int64_t ww = 0, wh = 0;
    call.method.extent(p, 0, &ww, &wh);
    Corners corners;
    if (p.levelling != 0) {
      ft_terrain_params raw = p;
      raw.levelling = 0, raw.height_offset = 0, raw.falloff = FT_FALLOFF_NONE, raw.sea = FT_SEA_NONE;
      raw.progress = nullptr;
      auto corner = [&](int64_t x, int64_t y) { return double(generate_terrain_window(raw, 0, x, y, 1, 1).at(0, 0)); };
      corners = Corners{corner(0, 0), corner(ww - 1, 0), corner(0, wh - 1), corner(ww - 1, wh - 1)};
    }
    const int64_t step = int64_t(1) << lod;
    apply_landforms(p, corners, Placement{x0 * step, y0 * step, step, ww, wh}, hf, p.threads);
    apply_sea(p, hf);
  }
  // The world size is the x extent of the samples: the window's share of it.
  hf.set_world_size(p.world_size * double(w - 1) / double(ew - 1));
  return hf;
}

ft_profile_params default_profile_params() { return defaults_of<ft_profile_params>(profile_param_table()); }

void validate_profile_params(const ft_profile_params& p) {
  check_struct_size(p.struct_size, sizeof(ft_profile_params), "ft_profile_params");
  check_ranges(profile_param_table(), &p);
  const double per_sigma = kMaxGaussian * (1 + p.levels);
  if (p.reference) {
    const int m = dyadic_levels(p.reference_size);
    if (m < 1 || m > p.levels)
      invalid("reference_size must be 2^m + 1 with 1 <= m <= levels (" + std::to_string(p.levels) + "); got " +
              std::to_string(p.reference_size));
    double top = 0;
    for (int32_t i = 0; i < p.reference_size; ++i) {
      if (!std::isfinite(p.reference[i]))
        invalid("reference value " + std::to_string(i) + " is " + format_number(p.reference[i]) + "; all must be finite");
      top = std::max(top, double(std::fabs(p.reference[i])));
    }
    const double sigma = reference_scale(p.reference_scale, p.sigma, p.reference, size_t(p.reference_size));
    check_height_bound(p.reference_scale == FT_REFSCALE_SIGMA ? "sigma" : "the reference scale", sigma, per_sigma, top);
  } else {
    check_height_bound("sigma", p.sigma, per_sigma);
  }
}

void generate_profile(const ft_profile_params& p, float* dst, size_t count) {
  validate_profile_params(p);
  check_not_null("dst", dst);
  const size_t need = (size_t(1) << p.levels) + 1;
  if (count < need)
    invalid("dst holds " + std::to_string(count) + " floats but levels " + std::to_string(p.levels) + " needs " +
            std::to_string(need));
  ProfileConfig c;
  c.levels = p.levels;
  c.hurst = p.hurst;
  c.seed = p.seed;
  c.progress = Progress(p.progress, p.progress_user);
  set_reference(c, p, size_t(p.reference_size));
  midpoint_profile(c, dst);
}

}  // namespace ft::terrain
