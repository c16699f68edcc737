// SPDX-License-Identifier: GPL-3.0-or-later
// Counter-based randomness (Random123 Philox4x32-10). A draw is a pure
// function of (seed, counter): the counter names *where* the number is used
// (stream, level, row, index), so any thread, tile or order of evaluation
// gets the same number for the same place.
//
// Counter layout used throughout fracterra: {index / 4, row, level, stream},
// the lane (index % 4) picks one of the four 32-bit outputs. Streams keep
// different uses of one seed apart (see the Stream enum).
#pragma once

#include <Random123/philox.h>

#include <cstddef>
#include <cstdint>

namespace ft {

// One stream per consumer of random numbers, so that, say, the corners of a
// terrain never reuse the numbers of its first midpoint.
enum class Stream : uint32_t {
  kTerrainCorners = 1,
  kTerrainSquare = 2,
  kTerrainDiamond = 3,
  kTerrainAddOld = 4,
  kTerrainAddNew = 5,       // additions: the points of a stage's coarse grid
  kTerrainAddHalf = 14,     // additions: the half-offset points new at a stage
  kProfile = 6,
  kInterpolated = 7,
  kSpectral = 8,
  kNoise = 9,               // fbm octave i: level i
  kNoiseWarpX = 15,         // domain warp, x field: level = octave
  kNoiseWarpY = 16,         // domain warp, y field: level = octave
  kFluvialRouting = 17,     // Rho8 receivers of the fluvial eroder: level = time step
  kFlatRouting = 18,        // the maps' step costs across flats (erosion/flat_resolution.hpp): level 0
  kRiverPlains = 19,        // the rivers' step costs across flats (hydrology/plains.cpp): level 0
  kPlanetNoise = 30,        // spherical fbm (planet/): level = octave
  kPlanetMidpoint = 31,     // spherical midpoint (planet/): {x, y, z} = the vertex's cube point at its birth level
  kPolyline = 10,
  kPolylineBranch = 11,
  kIfs = 12,
  kSubdiv = 13,
  kFirstUser = 64,
};

struct Counter {
  uint32_t row = 0;
  uint32_t level = 0;
  Stream stream = Stream::kTerrainCorners;
};

using Philox = r123::Philox4x32;

inline Philox::key_type philox_key(uint64_t seed) {
  Philox::key_type k = {{uint32_t(seed), uint32_t(seed >> 32)}};
  return k;
}

// The four 32-bit outputs of block `block` of the counter `c` (the reference
// scalar path; the batch fills below are bit-identical to it).
inline Philox::ctr_type philox_block(uint64_t seed, const Counter& c, uint32_t block) {
  Philox::ctr_type ctr = {{block, c.row, c.level, uint32_t(c.stream)}};
  return Philox()(ctr, philox_key(seed));
}

// 32 random bits for index `index` of counter `c`.
inline uint32_t random_bits(uint64_t seed, const Counter& c, uint64_t index) {
  return philox_block(seed, c, uint32_t(index >> 2)).v[index & 3];
}

// Uniform in the open interval (0, 1) from 32 bits: 24 bits of mantissa plus
// half a step, so neither 0 nor 1 is ever returned.
inline float bits_to_unit_open(uint32_t bits) {
  return float(bits >> 8) * (1.0f / 16777216.0f) + (0.5f / 16777216.0f);
}
inline double bits_to_unit_double(uint32_t hi, uint32_t lo) {
  return (double((uint64_t(hi) << 21) ^ (lo >> 11)) + 0.5) * (1.0 / 9007199254740992.0);
}

// N(0, 1) variates for indices first .. first + n - 1 of counter `c`, into
// out[0 .. n). Box-Muller on Philox output: index 4b + {0, 1} come from the
// pair (bits 0, bits 1) of block b, index 4b + {2, 3} from (bits 2, bits 3).
// Vectorised with runtime dispatch; every dispatch path gives the same bits.
void gaussian_fill(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out);
// Uniform variates in (0, 1), same addressing as gaussian_fill.
void uniform_fill(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out);
// The single N(0, 1) variate gaussian_fill would give for `index`.
float gaussian_at(uint64_t seed, const Counter& c, uint64_t index);

namespace detail {
// Box-Muller from two uniforms in (0, 1): returns the pair (r cos t, r sin t).
// Written without libm calls (polynomial log and sincos) so it vectorises and
// gives identical results on every path. Accuracy ~1e-7 relative.
void box_muller(float u1, float u2, float& z0, float& z1);
// The dispatch paths of gaussian_fill and uniform_fill, fastest last.
enum class RngPath { kBaseline, kAvx2, kAvx512 };
// Whether this CPU (and OS) can run a path.
bool rng_path_available(RngPath path);
// "avx512", "avx2" or "baseline": the path the fills take on this machine,
// the fastest available unless FT_DISPATCH=baseline or FT_DISPATCH=avx2 caps it.
const char* dispatch_path();
// The fills on a chosen path, which must be available (the tests and
// benchmarks compare the paths).
void gaussian_fill_on_path(RngPath path, uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out);
void uniform_fill_on_path(RngPath path, uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out);
}  // namespace detail

}  // namespace ft
