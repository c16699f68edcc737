// SPDX-License-Identifier: GPL-3.0-or-later
// The AVX-512 path of gaussian_fill and uniform_fill (see rng_paths.hpp):
// Philox4x32-10 and the polynomial Box-Muller of rng.cpp on 16 blocks at
// once, written out with intrinsics. Every operation is the one rng.cpp's
// scalar code does, in the same order and precision (IEEE add, mul, div and
// sqrt round the same at any width; -ffp-contract=off, no FMA), so the bits
// are the same (tests/native/core_test.cpp compares every path).
//
// Why by hand: on Zen 4 the compiler's AVX2 code spent ~1.9 ns a variate,
// half of a midpoint terrain's time. Here the 3-way XORs are one vpternlogd,
// the 64-bit products' halves are picked with masked shuffles instead of
// shift-and-blend pairs, float -> uint32 is one conversion, the quadrant's
// swap is a mask blend, the first two Philox rounds (whose inputs are mostly
// the same for every block) are half scalar, the uniforms' scaling is folded
// into the Box-Muller steps, four batches run interleaved, and the blocks'
// outputs are put in index order with unpacks on a permuted counter order.
#include <immintrin.h>

#include <algorithm>
#include <cstring>

#include "core/avx512.hpp"
#include "core/rng_paths.hpp"

namespace ft::detail {
namespace {

// The lane -> block order of a batch of 16 blocks: lane 4 j + r holds block
// 4 r + j. After the unpacks in store_interleaved, output vector r then holds
// blocks 4 r .. 4 r + 3 in order.
FT_AVX512 __m512i lane_blocks() { return _mm512_setr_epi32(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15); }

// The high and low 32 bits of x * m per lane (m < 2^32): the even lanes'
// products with one vpmuludq, the odd lanes' with another on x >> 32, and
// each half picked by a masked in-lane shuffle.
FT_AVX512 void mulhilo(__m512i x, __m512i m, __m512i& hi, __m512i& lo) {
  const __m512i pe = _mm512_mul_epu32(x, m);
  const __m512i po = _mm512_mul_epu32(_mm512_srli_epi64(x, 32), m);
  hi = _mm512_mask_shuffle_epi32(po, 0x5555, pe, _MM_PERM_DDBB);  // even lanes <- pe's high halves
  lo = _mm512_mask_shuffle_epi32(pe, 0xAAAA, po, _MM_PERM_CCAA);  // odd lanes <- po's low halves
}

constexpr int kXor3 = 0x96;  // vpternlogd truth table of a ^ b ^ c

struct Keys {
  uint32_t k0[10], k1[10];
};

// The round keys, and the parts of rounds 0 and 1 that are the same for
// every block of the call: round 0 multiplies the level (x2), the same for
// all blocks; round 1 multiplies round 0's x0, which came from it alone.
struct Prelude {
  uint32_t r0_x0, r0_x1;    // round 0's outputs x0, x1 (the same for every block)
  uint32_t r1_hi0, r1_lo0;  // round 1's M0 * x0: its high half, and its low half (round 1's x3)
};

Prelude prelude(const Counter& c, const Keys& k) {
  const uint64_t p1 = uint64_t(PHILOX_M4x32_1) * c.level;
  Prelude p{};
  p.r0_x0 = uint32_t(p1 >> 32) ^ c.row ^ k.k0[0];
  p.r0_x1 = uint32_t(p1);
  const uint64_t q0 = uint64_t(PHILOX_M4x32_0) * p.r0_x0;
  p.r1_hi0 = uint32_t(q0 >> 32);
  p.r1_lo0 = uint32_t(q0);
  return p;
}

// Philox4x32-10 of 16 blocks, counters first + lane_blocks(), as
// philox_rounds in rng.cpp (Random123's round: x0' = hi(M1 x2) ^ x1 ^ k0,
// x1' = lo(M1 x2), x2' = hi(M0 x0) ^ x3 ^ k1, x3' = lo(M0 x0)).
template <int N>
FT_AVX512 void philox16(uint32_t first, uint32_t stream, const Keys& k, const Prelude& p, __m512i (&x0)[N],
                        __m512i (&x1)[N], __m512i (&x2)[N], __m512i (&x3)[N]) {
  const __m512i m0 = _mm512_set1_epi32(int(PHILOX_M4x32_0)), m1 = _mm512_set1_epi32(int(PHILOX_M4x32_1));
  for (int j = 0; j < N; ++j) {
    __m512i hi, lo;
    // Round 0: only x0 (the block number) differs between blocks.
    const __m512i c0 = _mm512_add_epi32(_mm512_set1_epi32(int(first + 16 * j)), lane_blocks());
    mulhilo(c0, m0, hi, lo);
    const __m512i a2 = _mm512_xor_si512(hi, _mm512_set1_epi32(int(stream ^ k.k1[0])));
    const __m512i a3 = lo;
    // Round 1: x0 = r0_x0 and x1 = r0_x1 are the same for all blocks.
    mulhilo(a2, m1, hi, lo);
    x0[j] = _mm512_xor_si512(hi, _mm512_set1_epi32(int(p.r0_x1 ^ k.k0[1])));
    x1[j] = lo;
    x2[j] = _mm512_xor_si512(a3, _mm512_set1_epi32(int(p.r1_hi0 ^ k.k1[1])));
    x3[j] = _mm512_set1_epi32(int(p.r1_lo0));
  }
  for (int r = 2; r < 10; ++r) {
    for (int j = 0; j < N; ++j) {
      __m512i hi0, lo0, hi1, lo1;
      mulhilo(x0[j], m0, hi0, lo0);
      mulhilo(x2[j], m1, hi1, lo1);
      x0[j] = _mm512_ternarylogic_epi32(hi1, x1[j], _mm512_set1_epi32(int(k.k0[r])), kXor3);
      x2[j] = _mm512_ternarylogic_epi32(hi0, x3[j], _mm512_set1_epi32(int(k.k1[r])), kXor3);
      x1[j] = lo1;
      x3[j] = lo0;
    }
  }
}

// 2^25 u for u = bits_to_unit_open(bits), as a float: float(2 (bits >> 8) + 1).
// bits_to_unit_open adds 2^-25 to the exact k 2^-24 (k = bits >> 8 < 2^24),
// one rounding of (2 k + 1) 2^-25; converting the odd 25-bit integer 2 k + 1
// is one rounding of the same number scaled by 2^25, and a power of two
// scales a normal float exactly: the same bits, two operations fewer
// (core_test checks the identity for every k). log_unit and sincos_turn
// below take 2^25 u and fold the scale into their exponent arithmetic and
// their first multiply.
FT_AVX512 __m512 unit_scaled(__m512i bits) {
  return _mm512_cvtepi32_ps(_mm512_or_si512(_mm512_srli_epi32(bits, 7), _mm512_set1_epi32(1)));
}

FT_AVX512 __m512 unit_open(__m512i bits) { return _mm512_mul_ps(unit_scaled(bits), _mm512_set1_ps(0x1p-25f)); }

// log_unit of rng.cpp, of u given as y = 2^25 u: y's mantissa is u's, its
// exponent 25 more.
FT_AVX512 __m512 log_unit(__m512 y) {
  const __m512i bits = _mm512_castps_si512(y);
  __m512i mbits = _mm512_or_si512(_mm512_and_si512(bits, _mm512_set1_epi32(0x007fffff)), _mm512_set1_epi32(0x3f800000));
  const __mmask16 big = _mm512_cmpgt_epu32_mask(mbits, _mm512_set1_epi32(0x3fb504f3));
  mbits = _mm512_mask_sub_epi32(mbits, big, mbits, _mm512_set1_epi32(1 << 23));
  __m512i e = _mm512_sub_epi32(_mm512_and_si512(_mm512_srli_epi32(bits, 23), _mm512_set1_epi32(0xff)),
                               _mm512_set1_epi32(127 + 25));
  e = _mm512_mask_add_epi32(e, big, e, _mm512_set1_epi32(1));
  const __m512 m = _mm512_castsi512_ps(mbits), one = _mm512_set1_ps(1.0f);
  const __m512 t = _mm512_div_ps(_mm512_sub_ps(m, one), _mm512_add_ps(m, one));
  const __m512 t2 = _mm512_mul_ps(t, t);
  __m512 s = _mm512_mul_ps(t2, _mm512_set1_ps(2.0f / 9.0f));
  s = _mm512_mul_ps(t2, _mm512_add_ps(_mm512_set1_ps(2.0f / 7.0f), s));
  s = _mm512_mul_ps(t2, _mm512_add_ps(_mm512_set1_ps(2.0f / 5.0f), s));
  s = _mm512_mul_ps(t2, _mm512_add_ps(_mm512_set1_ps(2.0f / 3.0f), s));
  s = _mm512_mul_ps(t, _mm512_add_ps(_mm512_set1_ps(2.0f), s));
  return _mm512_add_ps(s, _mm512_mul_ps(_mm512_cvtepi32_ps(e), _mm512_set1_ps(0.693147180559945f)));
}

// sincos_turn of rng.cpp, of u given as y = 2^25 u: 4 u = 2^-23 y exactly.
FT_AVX512 void sincos_turn(__m512 y, __m512& s, __m512& c) {
  const __m512 q4 = _mm512_mul_ps(y, _mm512_set1_ps(0x1p-23f));
  const __m512i q = _mm512_cvttps_epu32(q4);
  const __m512 a = _mm512_mul_ps(_mm512_sub_ps(_mm512_sub_ps(q4, _mm512_cvtepu32_ps(q)), _mm512_set1_ps(0.5f)),
                                 _mm512_set1_ps(1.57079632679f));
  const __m512 a2 = _mm512_mul_ps(a, a);
  __m512 sa = _mm512_mul_ps(a2, _mm512_set1_ps(1.0f / 362880));
  sa = _mm512_mul_ps(a2, _mm512_add_ps(_mm512_set1_ps(-1.0f / 5040), sa));
  sa = _mm512_mul_ps(a2, _mm512_add_ps(_mm512_set1_ps(1.0f / 120), sa));
  sa = _mm512_mul_ps(a2, _mm512_add_ps(_mm512_set1_ps(-1.0f / 6), sa));
  sa = _mm512_mul_ps(a, _mm512_add_ps(_mm512_set1_ps(1.0f), sa));
  __m512 ca = _mm512_mul_ps(a2, _mm512_set1_ps(-1.0f / 3628800));
  ca = _mm512_mul_ps(a2, _mm512_add_ps(_mm512_set1_ps(1.0f / 40320), ca));
  ca = _mm512_mul_ps(a2, _mm512_add_ps(_mm512_set1_ps(-1.0f / 720), ca));
  ca = _mm512_mul_ps(a2, _mm512_add_ps(_mm512_set1_ps(1.0f / 24), ca));
  ca = _mm512_mul_ps(a2, _mm512_add_ps(_mm512_set1_ps(-0.5f), ca));
  ca = _mm512_add_ps(_mm512_set1_ps(1.0f), ca);
  const __m512 k = _mm512_set1_ps(0.70710678118f);
  const __m512 s0 = _mm512_mul_ps(_mm512_add_ps(ca, sa), k);
  const __m512 c0 = _mm512_mul_ps(_mm512_sub_ps(ca, sa), k);
  const __mmask16 odd = _mm512_test_epi32_mask(q, _mm512_set1_epi32(1));
  const __m512i sign = _mm512_set1_epi32(int(0x80000000u));
  // Sign of sin: bit 1 of q; of cos: bit 1 of q + 1 (shifted to bit 31).
  constexpr int kXorAnd = 0x78;  // a ^ (b & c)
  s = _mm512_castsi512_ps(_mm512_ternarylogic_epi32(_mm512_castps_si512(_mm512_mask_blend_ps(odd, s0, c0)),
                                                    _mm512_slli_epi32(q, 30), sign, kXorAnd));
  c = _mm512_castsi512_ps(_mm512_ternarylogic_epi32(_mm512_castps_si512(_mm512_mask_blend_ps(odd, c0, s0)),
                                                    _mm512_slli_epi32(_mm512_add_epi32(q, _mm512_set1_epi32(1)), 30),
                                                    sign, kXorAnd));
}

// box_muller of rng.cpp: (r cos t, r sin t), r = sqrt(-2 log u1), t = 2 pi u2;
// y1, y2 are 2^25 u1, 2^25 u2.
FT_AVX512 void box_muller(__m512 y1, __m512 y2, __m512& z0, __m512& z1) {
  const __m512 r = _mm512_sqrt_ps(_mm512_mul_ps(_mm512_set1_ps(-2.0f), log_unit(y1)));
  __m512 s, c;
  sincos_turn(y2, s, c);
  z0 = _mm512_mul_ps(r, c);
  z1 = _mm512_mul_ps(r, s);
}

FT_AVX512 __m512d pd(__m512 x) { return _mm512_castps_pd(x); }

// Writes the 64 values of 16 blocks in index order: v[k] holds output k of
// each block (lanes in lane_blocks() order).
FT_AVX512 void store_interleaved(const __m512 v[4], float* out) {
  const __m512 t0 = _mm512_unpacklo_ps(v[0], v[1]), t1 = _mm512_unpackhi_ps(v[0], v[1]);
  const __m512 t2 = _mm512_unpacklo_ps(v[2], v[3]), t3 = _mm512_unpackhi_ps(v[2], v[3]);
  _mm512_storeu_pd(out + 0, _mm512_unpacklo_pd(pd(t0), pd(t2)));
  _mm512_storeu_pd(out + 16, _mm512_unpackhi_pd(pd(t0), pd(t2)));
  _mm512_storeu_pd(out + 32, _mm512_unpacklo_pd(pd(t1), pd(t3)));
  _mm512_storeu_pd(out + 48, _mm512_unpackhi_pd(pd(t1), pd(t3)));
}

// 16 N blocks from block `first` on, written to out[0 .. 64 N).
template <bool kGaussian, int N>
FT_AVX512 void blocks16(uint32_t first, uint32_t stream, const Keys& k, const Prelude& p, float* out) {
  __m512i x0[N], x1[N], x2[N], x3[N];
  philox16<N>(first, stream, k, p, x0, x1, x2, x3);
  for (int j = 0; j < N; ++j) {
    __m512 v[4];
    if constexpr (kGaussian) {
      box_muller(unit_scaled(x0[j]), unit_scaled(x1[j]), v[0], v[1]);
      box_muller(unit_scaled(x2[j]), unit_scaled(x3[j]), v[2], v[3]);
    } else {
      v[0] = unit_open(x0[j]), v[1] = unit_open(x1[j]), v[2] = unit_open(x2[j]), v[3] = unit_open(x3[j]);
    }
    store_interleaved(v, out + 64 * j);
  }
}

template <bool kGaussian>
__attribute__((target("avx512f,avx512vl,avx512bw,avx512dq"))) void fill(uint64_t seed, const Counter& c,
                                                                        uint64_t first, size_t n, float* out) {
  Keys k;
  k.k0[0] = uint32_t(seed), k.k1[0] = uint32_t(seed >> 32);
  for (int r = 1; r < 10; ++r) k.k0[r] = k.k0[r - 1] + PHILOX_W32_0, k.k1[r] = k.k1[r - 1] + PHILOX_W32_1;
  const Prelude p = prelude(c, k);
  const uint32_t stream = uint32_t(c.stream);
  alignas(64) float tmp[64];
  // A head that starts inside a block, and a tail of fewer than 16 blocks,
  // go through a scratch batch.
  while (n > 0 && (first & 3) != 0) {
    blocks16<kGaussian, 1>(uint32_t(first >> 2), stream, k, p, tmp);
    const size_t take = std::min<size_t>(n, 4 - (first & 3));
    std::memcpy(out, tmp + (first & 3), take * sizeof(float));
    out += take, first += take, n -= take;
  }
  // Four batches at a time while they last: one batch's Philox rounds are a
  // chain of dependent multiplies (latency, not throughput, bound it), and
  // four independent chains fill the pipes (-20% time against one batch).
  uint32_t block = uint32_t(first >> 2);
  for (; n >= 256; n -= 256, out += 256, block += 64) blocks16<kGaussian, 4>(block, stream, k, p, out);
  for (; n >= 128; n -= 128, out += 128, block += 32) blocks16<kGaussian, 2>(block, stream, k, p, out);
  for (; n >= 64; n -= 64, out += 64, block += 16) blocks16<kGaussian, 1>(block, stream, k, p, out);
  if (n > 0) {
    blocks16<kGaussian, 1>(block, stream, k, p, tmp);
    std::memcpy(out, tmp, n * sizeof(float));
  }
}

}  // namespace

void gaussian_fill_avx512(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  fill<true>(seed, c, first, n, out);
}
void uniform_fill_avx512(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out) {
  fill<false>(seed, c, first, n, out);
}

}  // namespace ft::detail
