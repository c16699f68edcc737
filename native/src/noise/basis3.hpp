// SPDX-License-Identifier: GPL-3.0-or-later
// The noise bases of fbm in three dimensions (value, gradient, simplex,
// cellular F1 and F2 - F1), for fields on a sphere: a function of the 3D
// point has neither seams nor poles. Same habits as basis.hpp (no tables,
// selects only, integer hashing, always_inline into the caller's target).
//
// Precision: the lattice coordinates are doubles, split into an integer cell
// and a float offset inside it (cell3, simplex_cell3) before any float
// arithmetic. An Earth-radius planet at 2 m detail has lattice coordinates
// near 2^23 cells; in float their fraction would be gone. Coordinates must
// stay within +-2^30 (fbm3.hpp validates it). The split is its own step so
// the caller can run it in a loop of its own: the bases themselves are then
// float and int32 only, twice as many lanes per vector as doubles.
#pragma once

#include <cstdint>

#include "noise/basis.hpp"

namespace ft::noise::detail {

#define FT_INLINE [[gnu::always_inline]] inline

inline constexpr uint32_t kPrimeZ = 1720413743u;

// floor for |x| < 2^31, as floor_int (truncation, one step down for negative
// non-integers); vectorises (AVX2 converts 4 doubles to int32 at once).
FT_INLINE int32_t floor_int_d(double x) {
  const int32_t t = int32_t(x);
  return t - int32_t(x < double(t));
}

FT_INLINE uint32_t hash3(uint32_t key, uint32_t xp, uint32_t yp, uint32_t zp) {
  return (key ^ xp ^ yp ^ zp) * kHashMul;
}

// Perlin's (2002) gradients: the 12 edge midpoints of the cube, 4 of them
// twice to make 16, chosen by the top four (best mixed) bits of the hash.
FT_INLINE float grad3(uint32_t h, float x, float y, float z) {
  const uint32_t g = h >> 28;
  const float u = g < 8u ? x : y;
  const float v = g < 4u ? y : ((g == 12u) | (g == 14u) ? x : z);
  const float su = std::bit_cast<float>(std::bit_cast<uint32_t>(u) ^ ((g & 1u) << 31));
  const float sv = std::bit_cast<float>(std::bit_cast<uint32_t>(v) ^ ((g & 2u) << 30));
  return su + sv;
}

// Cell (i, j, k) of a lattice point and the offset inside it.
struct Cell3 {
  int32_t i, j, k;
  float fx, fy, fz;
};
FT_INLINE Cell3 cell3(double x, double y, double z) {
  const int32_t i = floor_int_d(x), j = floor_int_d(y), k = floor_int_d(z);
  return {i, j, k, float(x - double(i)), float(y - double(j)), float(z - double(k))};
}

// Perlin gradient noise in 3D, quintic fade. Range [-1, 1]: at a cell's
// centre, all eight dot products at their largest (1), the value is 1.
FT_INLINE float gradient_noise3(uint32_t key, const Cell3& c) {
  const uint32_t x0 = uint32_t(c.i) * kPrimeX, y0 = uint32_t(c.j) * kPrimeY, z0 = uint32_t(c.k) * kPrimeZ;
  const uint32_t x1 = x0 + kPrimeX, y1 = y0 + kPrimeY, z1 = z0 + kPrimeZ;
  const float fx = c.fx, fy = c.fy, fz = c.fz, gx = fx - 1.0f, gy = fy - 1.0f, gz = fz - 1.0f;
  const float n000 = grad3(hash3(key, x0, y0, z0), fx, fy, fz);
  const float n100 = grad3(hash3(key, x1, y0, z0), gx, fy, fz);
  const float n010 = grad3(hash3(key, x0, y1, z0), fx, gy, fz);
  const float n110 = grad3(hash3(key, x1, y1, z0), gx, gy, fz);
  const float n001 = grad3(hash3(key, x0, y0, z1), fx, fy, gz);
  const float n101 = grad3(hash3(key, x1, y0, z1), gx, fy, gz);
  const float n011 = grad3(hash3(key, x0, y1, z1), fx, gy, gz);
  const float n111 = grad3(hash3(key, x1, y1, z1), gx, gy, gz);
  const float u = fade(fx), v = fade(fy), w = fade(fz);
  return lerp(lerp(lerp(n000, n100, u), lerp(n010, n110, u), v), lerp(lerp(n001, n101, u), lerp(n011, n111, u), v),
              w);
}

// Value noise in 3D: quintic interpolation of lattice values in [-1, 1).
FT_INLINE float value_noise3(uint32_t key, const Cell3& c) {
  const uint32_t x0 = uint32_t(c.i) * kPrimeX, y0 = uint32_t(c.j) * kPrimeY, z0 = uint32_t(c.k) * kPrimeZ;
  const uint32_t x1 = x0 + kPrimeX, y1 = y0 + kPrimeY, z1 = z0 + kPrimeZ;
  const float v000 = lattice_value(hash3(key, x0, y0, z0)), v100 = lattice_value(hash3(key, x1, y0, z0));
  const float v010 = lattice_value(hash3(key, x0, y1, z0)), v110 = lattice_value(hash3(key, x1, y1, z0));
  const float v001 = lattice_value(hash3(key, x0, y0, z1)), v101 = lattice_value(hash3(key, x1, y0, z1));
  const float v011 = lattice_value(hash3(key, x0, y1, z1)), v111 = lattice_value(hash3(key, x1, y1, z1));
  const float u = fade(c.fx), v = fade(c.fy), w = fade(c.fz);
  return lerp(lerp(lerp(v000, v100, u), lerp(v010, v110, u), v), lerp(lerp(v001, v101, u), lerp(v011, v111, u), v),
              w);
}

// Simplex noise in 3D (Perlin 2001, Gustavson's formulation): four corners
// of the skewed tetrahedron, kernel (0.6 - r^2)^4, scale 32 (Gustavson's,
// range about [-1, 1]). The skew runs in double (it mixes the three
// coordinates: simplex_cell3 gives the skewed cell and the offset of the
// first corner), the rest in float. The tetrahedron's corner order follows
// the ranks of the offsets, as masks so the loop stays branch-free.
FT_INLINE Cell3 simplex_cell3(double x, double y, double z) {
  constexpr double kF3 = 1.0 / 3.0;
  constexpr double kG3d = 1.0 / 6.0;
  const double s = (x + y + z) * kF3;
  const int32_t i = floor_int_d(x + s), j = floor_int_d(y + s), k = floor_int_d(z + s);
  const double t = double(int64_t(i) + j + k) * kG3d;
  return {i, j, k, float((x - double(i)) + t), float((y - double(j)) + t), float((z - double(k)) + t)};
}
FT_INLINE float simplex_noise3(uint32_t key, const Cell3& c) {
  constexpr float kG3 = 1.0f / 6.0f;
  const int32_t i = c.i, j = c.j, k = c.k;
  const float x0 = c.fx, y0 = c.fy, z0 = c.fz;
  const bool gxy = x0 >= y0, gxz = x0 >= z0, gyz = y0 >= z0;
  // First step along the largest offset, second along the two largest.
  const float i1 = float(gxy & gxz), j1 = float(!gxy & gyz), k1 = float(!gxz & !gyz);
  const float i2 = float(gxy | gxz), j2 = float(!(gxy & !gyz)), k2 = float(!(gxz & gyz));
  const float x1 = x0 - i1 + kG3, y1 = y0 - j1 + kG3, z1 = z0 - k1 + kG3;
  const float x2 = x0 - i2 + 2.0f * kG3, y2 = y0 - j2 + 2.0f * kG3, z2 = z0 - k2 + 2.0f * kG3;
  const float x3 = x0 - 1.0f + 3.0f * kG3, y3 = y0 - 1.0f + 3.0f * kG3, z3 = z0 - 1.0f + 3.0f * kG3;
  const uint32_t xp = uint32_t(i) * kPrimeX, yp = uint32_t(j) * kPrimeY, zp = uint32_t(k) * kPrimeZ;
  const uint32_t h0 = hash3(key, xp, yp, zp);
  const uint32_t h1 = hash3(key, xp + (kPrimeX & -uint32_t(i1 > 0.0f)), yp + (kPrimeY & -uint32_t(j1 > 0.0f)),
                            zp + (kPrimeZ & -uint32_t(k1 > 0.0f)));
  const uint32_t h2 = hash3(key, xp + (kPrimeX & -uint32_t(i2 > 0.0f)), yp + (kPrimeY & -uint32_t(j2 > 0.0f)),
                            zp + (kPrimeZ & -uint32_t(k2 > 0.0f)));
  const uint32_t h3 = hash3(key, xp + kPrimeX, yp + kPrimeY, zp + kPrimeZ);
  float w0 = positive_part(0.6f - x0 * x0 - y0 * y0 - z0 * z0);
  float w1 = positive_part(0.6f - x1 * x1 - y1 * y1 - z1 * z1);
  float w2 = positive_part(0.6f - x2 * x2 - y2 * y2 - z2 * z2);
  float w3 = positive_part(0.6f - x3 * x3 - y3 * y3 - z3 * z3);
  w0 *= w0, w1 *= w1, w2 *= w2, w3 *= w3;
  const float n = (w0 * w0) * grad3(h0, x0, y0, z0) + (w1 * w1) * grad3(h1, x1, y1, z1) +
                  (w2 * w2) * grad3(h2, x2, y2, z2) + (w3 * w3) * grad3(h3, x3, y3, z3);
  return 32.0f * n;
}

// Cellular noise in 3D: one feature point per cell (centre plus a jitter of
// up to +-kJitter3/2 per axis), nearest two among the 3 x 3 x 3 cells. The
// search is exact for F1 when sqrt(3) (1 + J) / 2 <= (3 - J) / 2, i.e.
// J <= (3 - sqrt 3) / (1 + sqrt 3) = 0.464. Squared distances, as in 2D.
inline constexpr float kJitter3 = 0.45f;
FT_INLINE F12 cellular_noise3(uint32_t key, const Cell3& c) {
  float f1 = 1e30f, f2 = 1e30f;
  for (int dk = -1; dk <= 1; ++dk) {
    for (int dj = -1; dj <= 1; ++dj) {
      for (int di = -1; di <= 1; ++di) {
        const uint32_t h = hash3(key, uint32_t(c.i + di) * kPrimeX, uint32_t(c.j + dj) * kPrimeY,
                                 uint32_t(c.k + dk) * kPrimeZ);
        // Three 10-bit fractions from the upper, middle and lower-middle bits.
        const float jx = float(h >> 22) * (1.0f / 1024.0f) - 0.5f;
        const float jy = float((h >> 12) & 1023u) * (1.0f / 1024.0f) - 0.5f;
        const float jz = float((h >> 2) & 1023u) * (1.0f / 1024.0f) - 0.5f;
        const float dx = float(di) + 0.5f + kJitter3 * jx - c.fx;
        const float dy = float(dj) + 0.5f + kJitter3 * jy - c.fy;
        const float dz = float(dk) + 0.5f + kJitter3 * jz - c.fz;
        keep_nearest_two(dx * dx + dy * dy + dz * dz, f1, f2);
      }
    }
  }
  return {f1, f2};
}

#undef FT_INLINE

}  // namespace ft::noise::detail
