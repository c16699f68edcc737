// SPDX-License-Identifier: GPL-3.0-or-later
// fBm octave noise (Quilez, seed 004) in the FastNoiseLite style: one config,
// one dispatcher; every fractal variant is the same octave loop around one
// noise call, and domain warping is a separate pass over the coordinates.
//
//   t = sum_i a_i noise(M_i x),  M_i = f_i R(i rotation),  f_i = frequency lacunarity^i,
//   a_i = gain^i  (gain <= 0: lacunarity^-H, i.e. 2^-H at lacunarity 2)
//
// x runs over [0, 1) across the width (samples are x / width, y / width, so
// cells are square); `frequency` is the number of base-octave cells across
// the width. Periodic noise rounds every octave's frequency to a whole number
// of cells per period (across the width and across the height), wraps the
// lattice, and drops the rotation (a rotated lattice does not tile).
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "core/progress.hpp"

namespace ft::noise {

// The noise layer's own names for its bases and octave combinations. Their
// values are the ABI's FT_BASIS_* and FT_FBM_* (terrain.cpp checks this at
// compile time), so the terrain layer passes ft_terrain_params' fields on
// unchanged, while this layer does not include the public terrain header.
enum NoiseBasis : int32_t {
  kBasisValue = 0,       // lattice values, quintic interpolation
  kBasisGradient = 1,    // Perlin gradient noise
  kBasisSimplex = 2,     // simplex noise (not periodic)
  kBasisCellularF1 = 3,  // Voronoi distance to the nearest feature point
  kBasisCellularF2F1 = 4 // Voronoi F2 - F1
};
enum FbmVariant : int32_t {
  kFbmStandard = 0,
  kFbmRidged = 1,
  kFbmHybrid = 2,        // Musgrave's hybrid multifractal
  kFbmHetero = 3         // Musgrave's heterogeneous terrain
};

// Lattice coordinates above this lose sub-cell resolution in float (the ulp
// at 2^17 is 1/64 of a cell): an fbm whose finest octave reaches beyond it
// is refused rather than silently quantised.
inline constexpr double kMaxLatticeCoordinate = 131072.0;
inline constexpr int kMaxOctaves = 30;
inline constexpr double kMaxWarp = 64.0;

struct FbmConfig {
  int32_t width = 513, height = 513;
  int32_t octaves = 8;        // 1..30
  double lacunarity = 2.0;    // > 1
  double gain = 0.0;          // (0, 1]; <= 0: lacunarity^-H
  double hurst = 0.8;         // used when gain <= 0
  int32_t basis = kBasisGradient;
  int32_t variant = kFbmStandard;
  double frequency = 4.0;     // base-octave cells across the width, > 0
  double offset = 1.0;        // ridged / hybrid / hetero offset, finite
  double rotation = 0.5;      // radians per octave, finite
  double warp = 0.0;          // domain warp in base cells, 0..64
  double sigma = 1.0;         // output scale
  bool periodic = false;
  uint64_t seed = 1;
  int threads = 0;
  Progress progress;
};

// Throws ft::Error naming the field and its allowed range (octaves, NaN,
// lacunarity <= 1, finest octave beyond float resolution, ...).
// max_side: the largest width and height (whole terrains are held in memory;
// windows of larger ones are not).
void validate_fbm(const FbmConfig& c, int64_t max_side = 65536);
// The amplitude ratio actually used (gain, or lacunarity^-H).
double effective_gain(const FbmConfig& c);
// An upper bound on |height| / sigma over every sample fbm() can make with
// these settings, and (in `unscaled`) on the octave sum before its scale is
// applied. From the octave loop's recurrences with every noise value at its
// bound (1 for value, gradient and simplex noise; 3 for the cellular bases,
// whose F1 <= 1.17 and F2 <= 2 sqrt 2 cells within their 3 x 3 search), so
// sigma can be checked against float range before any work is done.
double fbm_height_bound(const FbmConfig& c, double* unscaled = nullptr);
// Validates, then fills a width x height heightfield. Output scale: standard
// and ridged are divided by sum a_i, so standard value/gradient/simplex fbm
// stays within [-sigma, sigma]; hybrid and hetero are multiplied by sigma only.
Heightfield fbm(const FbmConfig& c);
// The w x h samples from (x0, y0) of the terrain fbm(c) would make, bit for
// bit (every sample is a function of its global index). Callers validate.
Heightfield fbm_window(const FbmConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h);
// The same samples into the caller's w x h row-major buffer (every sample is
// written): for a caller that fills one buffer again and again, as a noise
// library's grid call does, without the kernel zeroing fresh pages each time.
void fbm_window_into(const FbmConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h, float* out);

namespace detail {
// Which compiled path runs the octave loop: kAuto picks the widest the CPU
// has (AVX-512, AVX2, the x86-64 baseline; FT_DISPATCH=avx2 or baseline caps
// it); kAvx2 caps it at AVX2, kBaseline forces the baseline build (test
// hooks: every path must give identical bits).
enum class SimdPath { kAuto, kAvx2, kBaseline };
void set_simd_path(SimdPath path);
// "avx512", "avx2" or "baseline": the path the next fbm call will take.
const char* active_simd_path();
}  // namespace detail

}  // namespace ft::noise
