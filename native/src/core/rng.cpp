// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rng.hpp"

#include "core/rng_paths.hpp"

#include <immintrin.h>

#include <bit>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace ft {
namespace {

// Natural log for x in (0, 1]: x = m * 2^e with m in [sqrt(1/2), sqrt(2)),
// log m = 2 atanh(t), t = (m - 1) / (m + 1), |t| <= 0.172 (series to t^9).
// Selects are integer arithmetic, not branches, so the loop vectorises.
__attribute__((always_inline)) inline float log_unit(float x) {
  const uint32_t bits = std::bit_cast<uint32_t>(x);
  uint32_t mbits = (bits & 0x007fffffu) | 0x3f800000u;  // m in [1, 2)
  const uint32_t big = mbits > 0x3fb504f3u;             // m > sqrt(2): halve it
  mbits -= big << 23;
  const int32_t e = int32_t((bits >> 23) & 0xff) - 127 + int32_t(big);
  const float m = std::bit_cast<float>(mbits);
  const float t = (m - 1.0f) / (m + 1.0f);
  const float t2 = t * t;
  const float series =
      t * (2.0f + t2 * (2.0f / 3.0f + t2 * (2.0f / 5.0f + t2 * (2.0f / 7.0f + t2 * (2.0f / 9.0f)))));
  return series + float(e) * 0.693147180559945f;
}

// sin and cos of 2 pi u for u in (0, 1): quadrant q from 4u, the angle within
// the quadrant centred on pi/4 so the Taylor series are short, then the
// quarter turns as a swap and sign flips on the bits (exact, branch-free).
__attribute__((always_inline)) inline void sincos_turn(float u, float& s, float& c) {
  const float q4 = u * 4.0f;
  const uint32_t q = uint32_t(q4);  // 0..3
  const float a = (q4 - float(q) - 0.5f) * 1.57079632679f;  // in [-pi/4, pi/4)
  const float a2 = a * a;
  const float sa = a * (1.0f + a2 * (-1.0f / 6 + a2 * (1.0f / 120 + a2 * (-1.0f / 5040 + a2 * (1.0f / 362880)))));
  const float ca = 1.0f + a2 * (-0.5f + a2 * (1.0f / 24 + a2 * (-1.0f / 720 + a2 * (1.0f / 40320 + a2 * (-1.0f / 3628800)))));
  const float k = 0.70710678118f;
  const uint32_t s0 = std::bit_cast<uint32_t>((ca + sa) * k);  // sin(pi/4 + a)
  const uint32_t c0 = std::bit_cast<uint32_t>((ca - sa) * k);  // cos(pi/4 + a)
  // q = 0: (s0, c0); 1: (c0, -s0); 2: (-s0, -c0); 3: (-c0, s0).
  const uint32_t swap = 0u - (q & 1u);
  const uint32_t sb = (s0 & ~swap) | (c0 & swap);
  const uint32_t cb = (c0 & ~swap) | (s0 & swap);
  s = std::bit_cast<float>(sb ^ ((q & 2u) << 30));
  c = std::bit_cast<float>(cb ^ (((q + 1u) & 2u) << 30));
}

__attribute__((always_inline)) inline void philox_rounds(uint32_t& c0, uint32_t& c1, uint32_t& c2, uint32_t& c3, uint32_t k0,
                          uint32_t k1) {
  // Philox4x32-10 exactly as Random123 defines it (constants from philox.h).
  for (int r = 0; r < 10; ++r) {
    if (r > 0) {
      k0 += PHILOX_W32_0;
      k1 += PHILOX_W32_1;
    }
    const uint64_t p0 = uint64_t(PHILOX_M4x32_0) * c0;
    const uint64_t p1 = uint64_t(PHILOX_M4x32_1) * c2;
    const uint32_t hi0 = uint32_t(p0 >> 32), lo0 = uint32_t(p0);
    const uint32_t hi1 = uint32_t(p1 >> 32), lo1 = uint32_t(p1);
    const uint32_t n0 = hi1 ^ c1 ^ k0;
    const uint32_t n1 = lo1;
    const uint32_t n2 = hi0 ^ c3 ^ k1;
    const uint32_t n3 = lo0;
    c0 = n0;
    c1 = n1;
    c2 = n2;
    c3 = n3;
  }
}

__attribute__((always_inline)) inline void box_muller_inline(float u1, float u2, float& z0, float& z1) {
  const float r = std::sqrt(-2.0f * log_unit(u1));
  float s, c;
  sincos_turn(u2, s, c);
  z0 = r * c;
  z1 = r * s;
}

constexpr size_t kChunk = 64;  // blocks per inner batch (256 variates)

// Philox4x32-10 on 8 counters at once with AVX2, kWays batches of 8 side by
// side (one batch's rounds are a chain of dependent multiplies; independent
// ones keep the pipes busy). The compiler's own vectorisation of
// philox_rounds spends most of its time on the 32x32->64 multiplies;
// _mm256_mul_epu32 on even and odd lanes does them in 6 instructions. Same
// bits as philox_rounds (the tests compare both paths).
template <int kWays>
__attribute__((target("avx2"), always_inline)) inline void philox_ways_avx2(uint32_t first_block, const Counter& c,
                                                                            uint32_t k0, uint32_t k1, uint32_t* b0,
                                                                            uint32_t* b1, uint32_t* b2, uint32_t* b3) {
  const __m256i m0 = _mm256_set1_epi32(int(PHILOX_M4x32_0)), m1 = _mm256_set1_epi32(int(PHILOX_M4x32_1));
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  __m256i x0[kWays], x1[kWays], x2[kWays], x3[kWays];
  for (int j = 0; j < kWays; ++j) {
    x0[j] = _mm256_add_epi32(_mm256_set1_epi32(int(first_block + uint32_t(8 * j))), lane);
    x1[j] = _mm256_set1_epi32(int(c.row)), x2[j] = _mm256_set1_epi32(int(c.level));
    x3[j] = _mm256_set1_epi32(int(uint32_t(c.stream)));
  }
  uint32_t key0 = k0, key1 = k1;
  for (int r = 0; r < 10; ++r) {
    if (r > 0) key0 += PHILOX_W32_0, key1 += PHILOX_W32_1;
    for (int j = 0; j < kWays; ++j) {
      // Products of even lanes, then of odd lanes (shifted down).
      const __m256i pe0 = _mm256_mul_epu32(x0[j], m0), po0 = _mm256_mul_epu32(_mm256_srli_epi64(x0[j], 32), m0);
      const __m256i pe1 = _mm256_mul_epu32(x2[j], m1), po1 = _mm256_mul_epu32(_mm256_srli_epi64(x2[j], 32), m1);
      const __m256i lo0 = _mm256_blend_epi32(pe0, _mm256_slli_epi64(po0, 32), 0xAA);
      const __m256i hi0 = _mm256_blend_epi32(_mm256_srli_epi64(pe0, 32), po0, 0xAA);
      const __m256i lo1 = _mm256_blend_epi32(pe1, _mm256_slli_epi64(po1, 32), 0xAA);
      const __m256i hi1 = _mm256_blend_epi32(_mm256_srli_epi64(pe1, 32), po1, 0xAA);
      x0[j] = _mm256_xor_si256(_mm256_xor_si256(hi1, x1[j]), _mm256_set1_epi32(int(key0)));
      x2[j] = _mm256_xor_si256(_mm256_xor_si256(hi0, x3[j]), _mm256_set1_epi32(int(key1)));
      x1[j] = lo1;
      x3[j] = lo0;
    }
  }
  for (int j = 0; j < kWays; ++j) {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(b0 + 8 * j), x0[j]);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(b1 + 8 * j), x1[j]);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(b2 + 8 * j), x2[j]);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(b3 + 8 * j), x3[j]);
  }
}

__attribute__((target("avx2"))) void philox_batch_avx2(uint32_t first_block, size_t m, const Counter& c,
                                                       uint32_t k0, uint32_t k1, uint32_t* b0, uint32_t* b1,
                                                       uint32_t* b2, uint32_t* b3) {
  size_t i = 0;
  for (; i + 32 <= m; i += 32)
    philox_ways_avx2<4>(first_block + uint32_t(i), c, k0, k1, b0 + i, b1 + i, b2 + i, b3 + i);
  for (; i + 8 <= m; i += 8)
    philox_ways_avx2<1>(first_block + uint32_t(i), c, k0, k1, b0 + i, b1 + i, b2 + i, b3 + i);
  for (; i < m; ++i) {
    uint32_t x0 = first_block + uint32_t(i), x1 = c.row, x2 = c.level, x3 = uint32_t(c.stream);
    philox_rounds(x0, x1, x2, x3, k0, k1);
    b0[i] = x0, b1[i] = x1, b2[i] = x2, b3[i] = x3;
  }
}

template <bool kGaussian, bool kAvx2>
__attribute__((always_inline)) inline void fill_blocks(uint64_t seed, const Counter& c, uint32_t first_block,
                                                       size_t blocks, float* out) {
  const uint32_t k0 = uint32_t(seed), k1 = uint32_t(seed >> 32);
  // Struct-of-arrays batches so the compiler vectorises across blocks.
  alignas(64) uint32_t b0[kChunk], b1[kChunk], b2[kChunk], b3[kChunk];
  for (size_t start = 0; start < blocks; start += kChunk) {
    const size_t m = blocks - start < kChunk ? blocks - start : kChunk;
    if constexpr (kAvx2) {
      philox_batch_avx2(first_block + uint32_t(start), m, c, k0, k1, b0, b1, b2, b3);
    } else {
      for (size_t i = 0; i < m; ++i) {
        uint32_t x0 = first_block + uint32_t(start + i), x1 = c.row, x2 = c.level, x3 = uint32_t(c.stream);
        philox_rounds(x0, x1, x2, x3, k0, k1);
        b0[i] = x0, b1[i] = x1, b2[i] = x2, b3[i] = x3;
      }
    }
    float* o = out + start * 4;
    for (size_t i = 0; i < m; ++i) {
      const float u0 = bits_to_unit_open(b0[i]), u1 = bits_to_unit_open(b1[i]);
      const float u2 = bits_to_unit_open(b2[i]), u3 = bits_to_unit_open(b3[i]);
      if constexpr (kGaussian) {
        float z0, z1, z2, z3;
        box_muller_inline(u0, u1, z0, z1);
        box_muller_inline(u2, u3, z2, z3);
        o[4 * i + 0] = z0;
        o[4 * i + 1] = z1;
        o[4 * i + 2] = z2;
        o[4 * i + 3] = z3;
      } else {
        o[4 * i + 0] = u0;
        o[4 * i + 1] = u1;
        o[4 * i + 2] = u2;
        o[4 * i + 3] = u3;
      }
    }
  }
}

template <bool kGaussian, bool kAvx2>
__attribute__((always_inline)) inline void fill_any(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  // Unaligned head and tail go through a 4-wide scratch block.
  while (n > 0 && (first & 3) != 0) {
    float tmp[4];
    fill_blocks<kGaussian, kAvx2>(seed, c, uint32_t(first >> 2), 1, tmp);
    *out++ = tmp[first & 3];
    ++first;
    --n;
  }
  const size_t blocks = n / 4;
  fill_blocks<kGaussian, kAvx2>(seed, c, uint32_t(first >> 2), blocks, out);
  first += blocks * 4;
  out += blocks * 4;
  n -= blocks * 4;
  if (n > 0) {
    float tmp[4];
    fill_blocks<kGaussian, kAvx2>(seed, c, uint32_t(first >> 2), 1, tmp);
    for (size_t i = 0; i < n; ++i) out[i] = tmp[i];
  }
}

}  // namespace

namespace detail {
void box_muller(float u1, float u2, float& z0, float& z1) { box_muller_inline(u1, u2, z0, z1); }
}  // namespace detail

// Runtime dispatch: the same kernel compiled for AVX2 and for baseline
// x86-64, and written out for AVX-512 (rng_avx512.cpp). -ffp-contract=off and
// libm-free math make all give the same bits; FT_DISPATCH=baseline or
// FT_DISPATCH=avx2 caps the path (tests compare them all).
namespace {
using FillFn = void (*)(uint64_t, const Counter&, uint64_t, size_t, float*);

__attribute__((target("avx2"))) void gaussian_fill_avx2(uint64_t seed, const Counter& c, uint64_t first, size_t n,
                                                        float* out) {
  fill_any<true, true>(seed, c, first, n, out);
}
void gaussian_fill_baseline(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  fill_any<true, false>(seed, c, first, n, out);
}
__attribute__((target("avx2"))) void uniform_fill_avx2(uint64_t seed, const Counter& c, uint64_t first, size_t n,
                                                       float* out) {
  fill_any<false, true>(seed, c, first, n, out);
}
void uniform_fill_baseline(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  fill_any<false, false>(seed, c, first, n, out);
}

constexpr FillFn kGaussianFills[] = {gaussian_fill_baseline, gaussian_fill_avx2, detail::gaussian_fill_avx512};
constexpr FillFn kUniformFills[] = {uniform_fill_baseline, uniform_fill_avx2, detail::uniform_fill_avx512};

detail::RngPath chosen_path() {
  using detail::RngPath;
  static const RngPath path = [] {
    const char* force = std::getenv("FT_DISPATCH");
    const std::string_view cap = force ? force : "";
    if (cap == "baseline") return RngPath::kBaseline;
    if (cap != "avx2" && detail::rng_path_available(RngPath::kAvx512)) return RngPath::kAvx512;
    return detail::rng_path_available(RngPath::kAvx2) ? RngPath::kAvx2 : RngPath::kBaseline;
  }();
  return path;
}
}  // namespace

void gaussian_fill(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  kGaussianFills[int(chosen_path())](seed, c, first, n, out);
}

void uniform_fill(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  kUniformFills[int(chosen_path())](seed, c, first, n, out);
}

namespace detail {
bool rng_path_available(RngPath path) {
  __builtin_cpu_init();
  switch (path) {
    case RngPath::kBaseline: return true;
    case RngPath::kAvx2: return __builtin_cpu_supports("avx2") != 0;
    case RngPath::kAvx512:
      return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
             __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
  }
  return false;
}
const char* dispatch_path() {
  static constexpr const char* kNames[] = {"baseline", "avx2", "avx512"};
  return kNames[int(chosen_path())];
}
void gaussian_fill_on_path(RngPath path, uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  kGaussianFills[int(rng_path_available(path) ? path : RngPath::kBaseline)](seed, c, first, n, out);
}
void uniform_fill_on_path(RngPath path, uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  kUniformFills[int(rng_path_available(path) ? path : RngPath::kBaseline)](seed, c, first, n, out);
}
}  // namespace detail

float gaussian_at(uint64_t seed, const Counter& c, uint64_t index) {
  const auto r = philox_block(seed, c, uint32_t(index >> 2));
  const unsigned pair = (index & 3) >> 1;
  float z0, z1;
  box_muller_inline(bits_to_unit_open(r.v[2 * pair]), bits_to_unit_open(r.v[2 * pair + 1]), z0, z1);
  return (index & 1) ? z1 : z0;
}

}  // namespace ft
