// SPDX-License-Identifier: GPL-3.0-or-later
// The noise bases of fbm (value, gradient, simplex, cellular F1 and F2 - F1),
// one sample at a time, written so that a loop over samples vectorises:
// no tables (gathers), no branches (selects only), float math, integer
// hashing. They are always_inline so each is compiled inside the caller's
// target (AVX2 or the x86-64 baseline, see fbm.cpp); with -ffp-contract=off
// every path performs the same IEEE operations and gives the same bits.
//
// Hashing: a lattice point (i, j) hashes to (key ^ i P1 ^ j P2) * M (the
// FastNoiseLite scheme); `key` is 32 bits of Philox output per octave
// (fbm.cpp), so the "permutation" of every octave is drawn from the
// counter-based generator and never from an order-dependent stream.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace ft::noise::detail {

#define FT_INLINE [[gnu::always_inline]] inline

inline constexpr uint32_t kPrimeX = 501125321u;
inline constexpr uint32_t kPrimeY = 1136930381u;
inline constexpr uint32_t kHashMul = 0x27d4eb2du;

// Lattice coordinates of one sample: the cell (i, j) and the position inside it.
struct Cell {
  int32_t i, j;
  float fx, fy;
};

// floor for |x| < 2^31 without libm (truncation, then one step down for
// negative non-integers), so it vectorises.
FT_INLINE int32_t floor_int(float x) {
  const int32_t t = int32_t(x);
  return t - int32_t(x < float(t));
}

FT_INLINE uint32_t hash2(uint32_t key, uint32_t xp, uint32_t yp) { return (key ^ xp ^ yp) * kHashMul; }

// Index i wrapped into [0, period) for periodic noise (period >= 1). The
// float quotient can be off by one at exact multiples; the two selects fix it.
FT_INLINE int32_t wrap(int32_t i, int32_t period, float inv_period) {
  int32_t w = i - period * floor_int(float(i) * inv_period);
  w = w >= period ? w - period : w;
  return w < 0 ? w + period : w;
}

// Gradient dot product. 8 directions evenly spaced by 45 degrees, starting
// at 22.5 degrees: (+-1, +-c) and (+-c, +-1) with c = tan(pi/8), so none is
// axis-aligned and no table lookup is needed. |g| = sqrt(1 + c^2).
inline constexpr float kTanPi8 = 0.41421356237f;
FT_INLINE float grad_dot(uint32_t h, float dx, float dy) {
  // The top three bits of the multiply (the best mixed) choose: bit 29
  // swaps the components, bits 31 and 30 flip their signs (XOR of the float
  // sign bit, cheaper than a select).
  const bool swap = int32_t(h << 2) < 0;
  const float a0 = swap ? dy : dx;
  const float b0 = swap ? dx : dy;
  const float a = std::bit_cast<float>(std::bit_cast<uint32_t>(a0) ^ (h & 0x80000000u));
  const float b = std::bit_cast<float>(std::bit_cast<uint32_t>(b0) ^ ((h << 1) & 0x80000000u));
  return a + kTanPi8 * b;
}

// Quintic fade 6t^5 - 15t^4 + 10t^3 (C2 continuous, Perlin 2002).
FT_INLINE float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
FT_INLINE float lerp(float a, float b, float t) { return a + t * (b - a); }

// Hashed lattice coordinates of the four corners of a cell, wrapped when the
// noise is periodic (px > 0: period in cells along x, py along y).
struct Corners {
  uint32_t x0, x1, y0, y1;
};
template <bool kPeriodic>
FT_INLINE Corners corners(int32_t i, int32_t j, int32_t px, int32_t py, float ipx, float ipy) {
  if constexpr (kPeriodic) {
    const int32_t i0 = wrap(i, px, ipx), j0 = wrap(j, py, ipy);
    const int32_t i1 = i0 + 1 == px ? 0 : i0 + 1, j1 = j0 + 1 == py ? 0 : j0 + 1;
    return {uint32_t(i0) * kPrimeX, uint32_t(i1) * kPrimeX, uint32_t(j0) * kPrimeY, uint32_t(j1) * kPrimeY};
  } else {
    const uint32_t x0 = uint32_t(i) * kPrimeX, y0 = uint32_t(j) * kPrimeY;
    return {x0, x0 + kPrimeX, y0, y0 + kPrimeY};
  }
}

// Perlin gradient noise, range [-1, 1], mean 0 (the gradients are symmetric).
// The largest |value| of 2D gradient noise with gradients of length |g| is
// |g| sqrt(2)/2 (cell centre, all four gradients pointing away), hence the
// factor 1 / (sqrt(1 + c^2) sqrt(1/2)) = 1.30656.
template <bool kPeriodic>
FT_INLINE float gradient_noise(uint32_t key, float x, float y, int32_t px, int32_t py, float ipx, float ipy) {
  const int32_t i = floor_int(x), j = floor_int(y);
  const float fx = x - float(i), fy = y - float(j);
  const Corners c = corners<kPeriodic>(i, j, px, py, ipx, ipy);
  const float n00 = grad_dot(hash2(key, c.x0, c.y0), fx, fy);
  const float n10 = grad_dot(hash2(key, c.x1, c.y0), fx - 1.0f, fy);
  const float n01 = grad_dot(hash2(key, c.x0, c.y1), fx, fy - 1.0f);
  const float n11 = grad_dot(hash2(key, c.x1, c.y1), fx - 1.0f, fy - 1.0f);
  const float u = fade(fx), v = fade(fy);
  return 1.30656296f * lerp(lerp(n00, n10, u), lerp(n01, n11, u), v);
}

// A lattice value uniform in [-1, 1): the hash squared and shuffled once more
// (FastNoiseLite's value hash), as a signed 32-bit fraction.
FT_INLINE float lattice_value(uint32_t h) {
  h *= h;
  h ^= h << 19;
  return float(int32_t(h)) * (1.0f / 2147483648.0f);
}

// Value noise: quintic interpolation of lattice values; range [-1, 1], mean 0.
template <bool kPeriodic>
FT_INLINE float value_noise(uint32_t key, float x, float y, int32_t px, int32_t py, float ipx, float ipy) {
  const int32_t i = floor_int(x), j = floor_int(y);
  const float fx = x - float(i), fy = y - float(j);
  const Corners c = corners<kPeriodic>(i, j, px, py, ipx, ipy);
  const float v00 = lattice_value(hash2(key, c.x0, c.y0)), v10 = lattice_value(hash2(key, c.x1, c.y0));
  const float v01 = lattice_value(hash2(key, c.x0, c.y1)), v11 = lattice_value(hash2(key, c.x1, c.y1));
  const float u = fade(fx), v = fade(fy);
  return lerp(lerp(v00, v10, u), lerp(v01, v11, u), v);
}

// max(w, 0) as a bit mask: GCC's if-conversion gives up on the simplex loop
// when this is written as a select, and the loop would not vectorise.
FT_INLINE float positive_part(float w) {
  return std::bit_cast<float>(std::bit_cast<uint32_t>(w) & uint32_t(-int32_t(w > 0.0f)));
}

// Simplex noise (Perlin 2001, Gustavson's 2D formulation): three corners of
// the skewed triangle, radial kernel (1/2 - r^2)^4. Range [-1, 1], mean 0:
// the scale 91 is just below 1 / sup sum_k (1/2 - r_k^2)^4 r_k |g| =
// 1 / (0.010080 * 1.08239) = 91.65 (sup found by a dense search over the
// triangle), so |value| <= 1 for any choice of gradients. Not periodic.
FT_INLINE float simplex_noise(uint32_t key, float x, float y) {
  constexpr float kF2 = 0.36602540378f;  // (sqrt(3) - 1) / 2
  constexpr float kG2 = 0.21132486540f;  // (3 - sqrt(3)) / 6
  const float s = (x + y) * kF2;
  const int32_t i = floor_int(x + s), j = floor_int(y + s);
  const float t = float(i + j) * kG2;
  const float x0 = x - (float(i) - t), y0 = y - (float(j) - t);
  // The lower triangle (x0 > y0) steps in x first, the upper in y: as a
  // mask, so the loop stays branch-free.
  const uint32_t lower = uint32_t(-int32_t(x0 > y0));
  const float i1 = float(int32_t(lower & 1u)), j1 = 1.0f - i1;
  const float x1 = x0 - i1 + kG2, y1 = y0 - j1 + kG2;
  const float x2 = x0 - 1.0f + 2.0f * kG2, y2 = y0 - 1.0f + 2.0f * kG2;
  const uint32_t xp = uint32_t(i) * kPrimeX, yp = uint32_t(j) * kPrimeY;
  const uint32_t h0 = hash2(key, xp, yp);
  const uint32_t h1 = hash2(key, xp + (kPrimeX & lower), yp + (kPrimeY & ~lower));
  const uint32_t h2 = hash2(key, xp + kPrimeX, yp + kPrimeY);
  float w0 = 0.5f - x0 * x0 - y0 * y0, w1 = 0.5f - x1 * x1 - y1 * y1, w2 = 0.5f - x2 * x2 - y2 * y2;
  w0 = positive_part(w0);
  w1 = positive_part(w1);
  w2 = positive_part(w2);
  w0 *= w0, w1 *= w1, w2 *= w2;
  const float n = (w0 * w0) * grad_dot(h0, x0, y0) + (w1 * w1) * grad_dot(h1, x1, y1) +
                  (w2 * w2) * grad_dot(h2, x2, y2);
  return 91.0f * n;
}

// Cellular (Worley) noise: one feature point per cell at the cell centre
// plus a jitter of up to +-kJitter/2 per axis, nearest two among the 3 x 3
// neighbouring cells. With kJitter = 0.65 the 3 x 3 search is exact for F1:
// the own cell's point is within sqrt(2) (1 + J)/2 = 1.167 of the sample and
// any point two cells away is at least (3 - J)/2 = 1.175 away.
// Returns squared distances; the caller takes the square roots (a separate
// loop, because sqrtf with errno handling would stop vectorisation here).
inline constexpr float kJitter = 0.65f;
struct F12 {
  float f1, f2;  // squared
};
// Keeps the nearest two squared distances f1 <= f2 after seeing d (selects only).
FT_INLINE void keep_nearest_two(float d, float& f1, float& f2) {
  const float m = d < f2 ? d : f2;
  f2 = d < f1 ? f1 : m;
  f1 = d < f1 ? d : f1;
}
// F1 (kF1) or F2 - F1, as distances, from the squared ones; `out` may be `f1`.
template <bool kF1>
FT_INLINE void cellular_distances(int n, const float* f1, const float* f2, float* out) {
  for (int i = 0; i < n; ++i) {
    const float d1 = std::sqrt(f1[i]);
    out[i] = kF1 ? d1 : std::sqrt(f2[i]) - d1;
  }
}
template <bool kPeriodic>
FT_INLINE F12 cellular_noise(uint32_t key, float x, float y, int32_t px, int32_t py, float ipx, float ipy) {
  const int32_t i = floor_int(x), j = floor_int(y);
  const float fx = x - float(i), fy = y - float(j);
  float f1 = 1e30f, f2 = 1e30f;
  for (int dj = -1; dj <= 1; ++dj) {
    for (int di = -1; di <= 1; ++di) {
      uint32_t xp, yp;
      if constexpr (kPeriodic) {
        xp = uint32_t(wrap(i + di, px, ipx)) * kPrimeX;
        yp = uint32_t(wrap(j + dj, py, ipy)) * kPrimeY;
      } else {
        xp = uint32_t(i + di) * kPrimeX;
        yp = uint32_t(j + dj) * kPrimeY;
      }
      const uint32_t h = hash2(key, xp, yp);
      // Two 16-bit fractions from the well-mixed upper and middle bits.
      const float jx = float(h >> 16) * (1.0f / 65536.0f) - 0.5f;
      const float jy = float((h >> 4) & 0xffffu) * (1.0f / 65536.0f) - 0.5f;
      const float dx = float(di) + 0.5f + kJitter * jx - fx;
      const float dy = float(dj) + 0.5f + kJitter * jy - fy;
      keep_nearest_two(dx * dx + dy * dy, f1, f2);
    }
  }
  return {f1, f2};
}

#undef FT_INLINE

}  // namespace ft::noise::detail
