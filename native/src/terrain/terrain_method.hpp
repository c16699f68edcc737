// SPDX-License-Identifier: GPL-3.0-or-later
// A terrain method is one row of one table (terrain_methods.hpp): the
// functions that configure, validate, bound, generate and window it, and
// what it can do. terrain.cpp's dispatchers, the parameter table's method
// masks (terrain_params.cpp), the tile sets' height ranges and the pipeline's
// erosion rule all read the row, so a new method is its file plus its row.
#pragma once

#include <any>
#include <cstdint>
#include <span>
#include <string>

#include "core/heightfield.hpp"
#include "fracterra/params.h"
#include "fracterra/terrain.h"
#include "terrain/window.hpp"

namespace ft::terrain {

// How a method's terrain tiles.
enum class Tiling {
  kNever,      // no periodic form (the Mandelbrot set)
  kOnRequest,  // when ft_terrain_params.periodic is set
  kAlways,     // by construction (spectral synthesis: one FFT grid)
};

struct TerrainMethod {
  ft_param_enum_item item;  // the method enum's value, name, label and doc (the parameter table's items)

  // Capabilities.
  bool dyadic = false;      // (2^levels + 1)^2 samples from `levels`; otherwise width x height
  bool seeded = true;       // random: uses hurst and seed
  Tiling tiling = Tiling::kNever;
  // A periodic grid's period is its size less this: 1 when the last row and
  // column repeat the first (dyadic grids), 0 when the period is the grid.
  int32_t period_overlap = 0;
  bool reference = false;   // refines a reference grid (ft_terrain_params.reference)
  bool lod = false;         // windows at a level of detail (every 2^lod-th sample is a coarser stage)
  // Every coarser stage's samples keep their values in the finer ones (plain
  // midpoint): a coarse pass plus a margin bounds the heights (tiles/height_range).
  bool stages_keep_samples = false;

  // The functions. The configuration is the generator's own struct, built
  // once per call from the params (after the table's range checks) and
  // handed to the others.
  std::any (*configure)(const ft_terrain_params& p) = nullptr;
  // The method's own cross-field checks (null: none); max_side is the
  // largest side a whole terrain (65536) or a window's terrain may have.
  void (*validate)(const std::any& config, int64_t max_side) = nullptr;
  // Throws when heights could leave the float range (check_height_bound).
  void (*check_heights)(const std::any& config, const ft_terrain_params& p) = nullptr;
  Heightfield (*generate)(const std::any& config) = nullptr;
  // Null: no windows; no_windows says why.
  Heightfield (*window)(const std::any& config, const Window& w, int lod) = nullptr;
  const char* no_windows = nullptr;
  // The whole terrain's samples per side at level of detail lod.
  void (*extent)(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height) = nullptr;
  // Bytes a window's generation holds at its peak beside the result (null: none).
  uint64_t (*window_work_bytes)(int lod, int32_t w, int32_t h) = nullptr;
  // Null, or the exact height range [lo, hi] known from the parameters alone.
  void (*height_range)(const ft_terrain_params& p, double* lo, double* hi) = nullptr;
};

// The row of `method`; throws naming the methods for an unknown one.
const TerrainMethod& terrain_method(int32_t method);
std::span<const TerrainMethod> terrain_methods();
// Whether a terrain of these params tiles (its method always does, or on request and p.periodic is set).
bool tiles_periodically(const ft_terrain_params& p);
// "midpoint, additions or fbm": the methods whose row passes `has`, by their CLI names.
std::string methods_that(bool (*has)(const TerrainMethod&));

// Shared by the methods' files.

// log2(size - 1) when size is 2^m + 1 with m >= 1, else -1.
int dyadic_levels(int64_t size);

// Float range. Heights are float32: a sigma large enough to overflow them
// (`--sigma 1e300`) used to be noticed only when the file was written, after
// the work. Each method's check_heights bounds the largest |height| it can
// make, B = max|reference| + sigma * S, with S the largest possible sum of
// the displacements that reach one sample in units of sigma (its file
// derives S). One Gaussian is at most kMaxGaussian: Box-Muller's radius
// sqrt(-2 ln u) at the smallest uniform the RNG gives, u = 2^-25 (24 bits,
// half a step from 0): sqrt(50 ln 2) = 5.89. B must stay below FLT_MAX / 8:
// the generators add four neighbours before averaging and every consumer
// takes max - min. check_height_bound throws unless base + sigma * per_sigma
// stays below kMaxFloatHeight, naming `what` and its largest allowed value.
inline constexpr double kMaxGaussian = 5.9;
inline constexpr double kMaxFloatHeight = 3.4028234663852886e38 / 8;
void check_height_bound(const std::string& what, double sigma, double per_sigma, double base = 0);

// The displacement scale when refining from reference values (seed 000 tried
// sigma = 1 and the mean of the reference values): sigma, the mean |value| or
// the standard deviation of the `count` values. Throws when it is 0.
double reference_scale(int mode, double sigma, const float* reference, size_t count);

// The reference values and the refinement's scale of a midpoint config
// (DiamondSquareConfig, ProfileConfig) from its params, in one place.
template <class Config, class Params>
void set_reference(Config& c, const Params& p, size_t count) {
  c.sigma = p.sigma;
  if (!p.reference) return;
  c.reference = p.reference;
  c.ref_levels = dyadic_levels(p.reference_size);
  c.sigma = reference_scale(p.reference_scale, p.sigma, p.reference, count);
}

// The extents: (2^(levels - lod) + 1)^2, or width x height at lod 0.
void dyadic_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height);
void sized_extent(const ft_terrain_params& p, int lod, int64_t* width, int64_t* height);

}  // namespace ft::terrain
