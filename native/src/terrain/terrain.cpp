#include "terrain/terrain.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "noise/fbm.hpp"
#include "terrain/diamond_square.hpp"
#include "terrain/interpolated.hpp"
#include "terrain/landform.hpp"
#include "terrain/mandelbrot.hpp"
#include "terrain/profile.hpp"
#include "terrain/spectral_synthesis.hpp"
#include "terrain/terrain_params.hpp"
#include "terrain/window.hpp"

namespace ft {
namespace {

// The displacement scale when refining from reference values (seed 000 tried
// sigma = 1 and the mean of the reference values).
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

// The noise layer's enums carry the ABI's values, so basis and variant pass through.
static_assert(int(noise::kBasisValue) == FT_BASIS_VALUE && int(noise::kBasisGradient) == FT_BASIS_GRADIENT &&
              int(noise::kBasisSimplex) == FT_BASIS_SIMPLEX && int(noise::kBasisCellularF1) == FT_BASIS_CELLULAR_F1 &&
              int(noise::kBasisCellularF2F1) == FT_BASIS_CELLULAR_F2F1);
static_assert(int(noise::kFbmStandard) == FT_FBM_STANDARD && int(noise::kFbmRidged) == FT_FBM_RIDGED &&
              int(noise::kFbmHybrid) == FT_FBM_HYBRID && int(noise::kFbmHetero) == FT_FBM_HETERO);

// Float range. Heights are float32: a sigma large enough to overflow them
// (`--sigma 1e300`) used to be noticed only when the file was written, after
// the work. The check bounds the largest |height| a method can make, B =
// max|reference| + sigma * S, with S the largest possible sum of the
// displacements that reach one sample in units of sigma:
//  - one Gaussian is at most kMaxGaussian: Box-Muller's radius sqrt(-2 ln u)
//    at the smallest uniform the RNG gives, u = 2^-25 (24 bits, half a step
//    from 0): sqrt(50 ln 2) = 5.89;
//  - midpoint / additions: the corners, then at most 4 displacements per
//    level (its creation, and the additions of the square and diamond
//    steps), each at most sigma: S = 6 (1 + 4 levels) (Voss 1985);
//  - the Voss profile: one per level: S = 6 (1 + levels);
//  - interpolated: the corners plus one per cycle, each <= sigma;
//  - spectral: |sum c_k| <= sqrt(N) (sum |c_k|^2)^(1/2) over the N = W H
//    coefficients (Cauchy-Schwarz), whose power is scaled to sigma^2 with
//    |g| <= 6 on both parts: S = 6 sqrt(2 W H);
//  - fbm: fbm_height_bound, the octave recurrences at the noise's bound.
// B must stay below FLT_MAX / 8: the generators add four neighbours before
// averaging and every consumer takes max - min.
constexpr double kMaxGaussian = 5.9;
constexpr double kHeightLimit = 3.4028234663852886e38 / 8;

void check_height_bound(const std::string& what, double sigma, double per_sigma, double base = 0) {
  const double bound = base + sigma * per_sigma;
  if (bound <= kHeightLimit) return;
  invalid(what + " " + format_number(sigma) + " is too large: heights could reach " + format_number(bound) +
          ", beyond the float range (" + format_number(kHeightLimit) + " with headroom); for these settings it must "
          "be at most " + format_number((kHeightLimit - base) / per_sigma));
}

noise::FbmConfig fbm_config(const ft_terrain_params& p) {
  noise::FbmConfig c;
  c.width = p.width, c.height = p.height, c.octaves = p.octaves, c.lacunarity = p.lacunarity;
  c.gain = p.gain, c.hurst = p.hurst, c.basis = p.basis, c.variant = p.variant;
  c.frequency = p.frequency, c.offset = p.offset, c.rotation = p.octave_rotation, c.warp = p.warp;
  c.sigma = p.sigma, c.periodic = p.periodic != 0, c.seed = p.seed, c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

// The float-range check above for each method (after the other checks, so
// the sizes and counts it uses are valid).
void check_terrain_heights(const ft_terrain_params& p) {
  switch (p.method) {
    case FT_TERRAIN_MIDPOINT:
    case FT_TERRAIN_ADDITIONS: {
      const double per_sigma = kMaxGaussian * (1 + 4.0 * p.levels);
      if (!p.reference) return check_height_bound("sigma", p.sigma, per_sigma);
      const size_t n = size_t(p.reference_size) * size_t(p.reference_size);
      double top = 0;
      for (size_t i = 0; i < n; ++i) top = std::max(top, double(std::fabs(p.reference[i])));
      const double sigma = reference_scale(p.reference_scale, p.sigma, p.reference, n);
      return check_height_bound(p.reference_scale == FT_REFSCALE_SIGMA ? "sigma" : "the reference scale", sigma,
                                per_sigma, top);
    }
    case FT_TERRAIN_MANDELBROT:  // h = sigma (1 - (1 + s)^(-1/2)) lies in [0, sigma)
      return check_height_bound("sigma", p.sigma, 1.0);
    case FT_TERRAIN_SPECTRAL:
      return check_height_bound("sigma", p.sigma, kMaxGaussian * std::sqrt(2.0 * p.width * p.height));
    case FT_TERRAIN_INTERPOLATED: {
      const double d0 = std::max(p.width, p.height);
      return check_height_bound("sigma", p.sigma, kMaxGaussian * (2 + std::ceil(std::log(d0) / std::log(p.lacunarity))));
    }
    default: {
      double unscaled = 0;
      const double per_sigma = noise::fbm_height_bound(fbm_config(p), &unscaled);
      if (!(unscaled <= kHeightLimit))
        invalid("the fbm octave sum could reach " + format_number(unscaled) + " with offset " +
                format_number(p.offset) + " and " + std::to_string(p.octaves) +
                " octaves, beyond the float range; use a smaller |offset| or fewer octaves");
      return check_height_bound("sigma", p.sigma, per_sigma);
    }
  }
}

MandelbrotConfig mandelbrot_config(const ft_terrain_params& p) {
  MandelbrotConfig c;
  c.width = p.width, c.height = p.height, c.center_x = p.center_x, c.center_y = p.center_y;
  c.zoom = p.zoom, c.iterations = p.iterations, c.sigma = p.sigma, c.threads = p.threads;
  c.supersample = p.supersample;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

}  // namespace

int dyadic_levels(int64_t size) {
  if (size < 3) return -1;
  const int64_t n = size - 1;
  if ((n & (n - 1)) != 0) return -1;
  int m = 0;
  while ((int64_t(1) << m) < n) ++m;
  return m;
}

ft_terrain_params default_terrain_params() { return defaults_of<ft_terrain_params>(terrain_param_table()); }

namespace {

// The checks of every terrain; `whole` adds the size limits of a terrain
// held in memory, otherwise those of windows (which never hold the whole).
void validate_terrain(const ft_terrain_params& p, bool whole) {
  check_struct_size(p.struct_size, sizeof(ft_terrain_params), "ft_terrain_params");
  // The ranges of every field the method uses come from the table; what
  // follows relates fields to each other. The table's levels and sizes are
  // those of a whole terrain: a window's larger ones are checked here first.
  ft_terrain_params q = p;
  if (!whole) {
    if (p.method == FT_TERRAIN_MIDPOINT || p.method == FT_TERRAIN_ADDITIONS) {
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
  if (p.method == FT_TERRAIN_MIDPOINT || p.method == FT_TERRAIN_ADDITIONS) {
    const uint64_t side = (uint64_t(1) << p.levels) + 1;
    if (whole)
      check_allocation(checked_bytes(side, side, sizeof(float)),
                       "a terrain of levels " + std::to_string(p.levels) + " (" + std::to_string(side) + " x " +
                           std::to_string(side) + " samples); windows of it (ft_terrain_generate_window) need not fit");
    if (p.reference) check_reference(p.reference, p.reference_size, p.levels, p.periodic != 0);
  } else {
    if (whole)
      check_allocation(checked_bytes(uint64_t(p.width), uint64_t(p.height), sizeof(float)),
                       "a " + std::to_string(p.width) + " x " + std::to_string(p.height) + " terrain");
    if (p.reference) invalid("reference points are supported by the midpoint and additions methods only");
    if (p.method == FT_TERRAIN_FBM) noise::validate_fbm(fbm_config(p), max_side);
    if (p.method == FT_TERRAIN_INTERPOLATED) check_interpolated_lacunarity(p.lacunarity);
    if (p.method == FT_TERRAIN_MANDELBROT) validate_mandelbrot(mandelbrot_config(p), max_side);
  }
  check_terrain_heights(p);
  validate_landforms(p, whole);
}

}  // namespace

void validate_terrain_params(const ft_terrain_params& p) { validate_terrain(p, true); }

namespace {

DiamondSquareConfig diamond_square_config(const ft_terrain_params& p) {
  DiamondSquareConfig c;
  c.levels = p.levels;
  c.hurst = p.hurst;
  c.seed = p.seed;
  c.periodic = p.periodic != 0;
  c.additions = p.method == FT_TERRAIN_ADDITIONS;
  c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  c.sigma = p.sigma;
  if (p.reference) {
    c.reference = p.reference;
    c.ref_levels = dyadic_levels(p.reference_size);
    c.sigma = reference_scale(p.reference_scale, p.sigma, p.reference,
                              size_t(p.reference_size) * size_t(p.reference_size));
  }
  return c;
}

// The generator of one method, without the world size.
Heightfield generate_terrain_samples(const ft_terrain_params& p) {
  switch (p.method) {
    case FT_TERRAIN_MIDPOINT:
    case FT_TERRAIN_ADDITIONS:
      return diamond_square(diamond_square_config(p));
    case FT_TERRAIN_FBM:
      return noise::fbm(fbm_config(p));
    case FT_TERRAIN_SPECTRAL:
      return spectral_synthesis({p.width, p.height, p.hurst, p.sigma, p.seed, p.threads,
                                 Progress(p.progress, p.progress_user)});
    case FT_TERRAIN_INTERPOLATED:
      return interpolated_fm({p.width, p.height, p.lacunarity, p.hurst, p.sigma, p.seed, p.periodic != 0,
                              p.threads, Progress(p.progress, p.progress_user)});
    case FT_TERRAIN_MANDELBROT:
      return mandelbrot(mandelbrot_config(p));
  }
  // validate_terrain_params admits only the methods above: reaching here means a
  // method was added to the range check without a generator.
  fail(FT_ERR_INTERNAL, "terrain method " + std::to_string(p.method) + " passed validation but has no generator");
}

}  // namespace

Heightfield generate_terrain(const ft_terrain_params& p) {
  validate_terrain_params(p);
  // Every method records the world size here, in one place: it used to be
  // set by the midpoint branch only, so fbm, spectral and interpolated
  // terrains lost it (and `coastline --world` refused them).
  Heightfield hf = generate_terrain_samples(p);
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

bool dyadic_method(const ft_terrain_params& p) {
  return p.method == FT_TERRAIN_MIDPOINT || p.method == FT_TERRAIN_ADDITIONS;
}

// Bytes a window's generation holds at its peak, beside the result.
uint64_t window_work_bytes(const ft_terrain_params& p, int lod, int32_t w, int32_t h) {
  if (!dyadic_method(p)) return 0;
  // Plain midpoint writes its last stage straight into the window and
  // alternates two arrays for the stages before it (a quarter and a
  // sixteenth of it, halo included; bounded here by two quarters).
  // Additions hold the last stage's array (the window grown by its halo) and
  // the stage before it; at lod > 0 they refine the footprint.
  if (p.method == FT_TERRAIN_MIDPOINT)
    return checked_bytes(uint64_t(w) / 2 + 16, uint64_t(h) / 2 + 16, sizeof(float) * 2);
  const uint64_t k = uint64_t(1) << lod;
  const uint64_t fw = (uint64_t(w) - 1) * k + 1 + 16, fh = (uint64_t(h) - 1) * k + 1 + 16;
  return checked_bytes(fw, fh, sizeof(float) * (k > 1 ? 3 : 2));
}

}  // namespace

void terrain_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height) {
  validate_terrain(p, false);
  if (p.method == FT_TERRAIN_SPECTRAL)
    invalid("spectral synthesis has no windows: it is one global FFT, every sample depends on every Fourier "
            "coefficient, so a window costs the whole terrain; generate it whole (up to 65536 x 65536), or use "
            "windows of midpoint, additions, fbm or interpolated terrains");
  if (dyadic_method(p)) {
    check_int_range("lod", lod, 0, p.levels);
    *width = *height = (int64_t(1) << (p.levels - lod)) + 1;
    return;
  }
  if (lod != 0)
    invalid("a level of detail (lod " + std::to_string(lod) + ") is defined for midpoint and additions terrains, "
            "whose every 2^lod-th sample is a coarser stage; use lod 0 for other methods");
  *width = p.width, *height = p.height;
}

Heightfield generate_terrain_window(const ft_terrain_params& p, int lod, int64_t x0, int64_t y0, int32_t w,
                                    int32_t h) {
  int64_t ew = 0, eh = 0;
  terrain_extent(p, lod, &ew, &eh);
  if (w < 1 || h < 1)
    invalid("a window needs at least 1 x 1 samples, got " + std::to_string(w) + " x " + std::to_string(h));
  if (x0 < 0 || y0 < 0 || x0 > ew - w || y0 > eh - h)
    invalid("the window [" + std::to_string(x0) + ", " + std::to_string(x0 + w) + ") x [" + std::to_string(y0) +
            ", " + std::to_string(y0 + h) + ") lies outside the terrain's " + std::to_string(ew) + " x " +
            std::to_string(eh) + " samples" + (lod ? " at lod " + std::to_string(lod) : std::string()));
  check_allocation(checked_bytes(uint64_t(w), uint64_t(h), sizeof(float)) + window_work_bytes(p, lod, w, h),
                   "a " + std::to_string(w) + " x " + std::to_string(h) + " window");
  Heightfield hf;
  switch (p.method) {
    case FT_TERRAIN_MIDPOINT:
    case FT_TERRAIN_ADDITIONS:
      hf = diamond_square_window(diamond_square_config(p), Window{x0, y0, w, h}, lod);
      break;
    case FT_TERRAIN_FBM:
      hf = noise::fbm_window(fbm_config(p), x0, y0, w, h);
      break;
    case FT_TERRAIN_MANDELBROT:
      hf = mandelbrot_window(mandelbrot_config(p), x0, y0, w, h);
      break;
    case FT_TERRAIN_INTERPOLATED: {
      InterpolatedConfig c{p.width, p.height, p.lacunarity, p.hurst, p.sigma, p.seed, p.periodic != 0, p.threads,
                           Progress(p.progress, p.progress_user)};
      hf = interpolated_window(c, x0, y0, w, h);
      break;
    }
    default:
      fail(FT_ERR_INTERNAL, "terrain method " + std::to_string(p.method) + " has no window generator");
  }
  if (has_landforms(p)) {
    // The levelling needs the whole terrain's corners: four 1 x 1 windows
    // (for midpoint a chain of tiny halos, for the others one sample each).
    int64_t ww = 0, wh = 0;
    terrain_extent(p, 0, &ww, &wh);
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
  c.sigma = p.sigma;
  if (p.reference) {
    c.reference = p.reference;
    c.ref_levels = dyadic_levels(p.reference_size);
    c.sigma = reference_scale(p.reference_scale, p.sigma, p.reference, size_t(p.reference_size));
  }
  midpoint_profile(c, dst);
}

}  // namespace ft
