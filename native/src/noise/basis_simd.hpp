// SPDX-License-Identifier: GPL-3.0-or-later
// The value, gradient and simplex bases of flat, non-periodic fbm written
// with explicit AVX2 and AVX-512 vectors (the octave loop's hottest rows),
// for the dispatch paths of fbm.cpp (its only includer: they are defined
// here, so that adding them changed no other file's unity batch). They
// perform the same IEEE operations in the same order as basis.hpp's
// sample-at-a-time code, so every path gives the same bits; what they save
// is work that is not arithmetic on the result: floor by one rounding
// instruction instead of a conversion round trip, the gradient of a corner
// by two register permutes instead of selects and sign flips, and the
// v-products of a row computed once.
//
// simd_avx2::noise_row and simd_avx512::noise_row(basis, o, n, u, v, v_const, mode, amp, out):
// noise(M (u, v) + o) of basis 0, 1 or 2 (value, gradient, simplex) for the
// n <= 256 samples at u[i], v[i], as basis.hpp's value_noise,
// gradient_noise<false> and simplex_noise give them, into out[i] (mode
// kStore), or as the standard fbm's octave sum: out[i] = amp * noise
// (kFirst), out[i] += amp * noise (kAdd). v_const: every v[i] equals v[0]
// (a row without warp). Each is compiled for its instruction set: call it
// only where the CPU has it.
#pragma once

#include <immintrin.h>

#include <cstdint>

#include "noise/basis.hpp"
#include "noise/octave.hpp"

// gcc 12 warns inside its own AVX-512 headers once they are inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace ft::noise::detail {

// What a row does with its noise: stores it, or (the standard fbm's octave
// sum, octave_sum.hpp's add_octave fused in) stores amp * noise for the
// first octave and adds amp * noise to out[] for the others.
enum RowMode { kStore, kFirst, kAdd };

// gcc compiles a region for a target by `#pragma GCC target`; clang (the
// fuzz build) ignores that pragma and takes `#pragma clang attribute` instead.
#if defined(__clang__)
#pragma clang attribute push(__attribute__((target("avx2"))), apply_to = function)
#else
#pragma GCC push_options
#pragma GCC target("avx2")
#endif
namespace simd_avx2 {
constexpr int W = 8;
typedef float vf __attribute__((vector_size(32)));
typedef int32_t vi __attribute__((vector_size(32)));
typedef uint32_t vu __attribute__((vector_size(32)));
[[gnu::always_inline]] inline vf loadu(const float* p) { return vf(_mm256_loadu_ps(p)); }
[[gnu::always_inline]] inline void storeu(float* p, vf x) { _mm256_storeu_ps(p, __m256(x)); }
[[gnu::always_inline]] inline vf floorv(vf x) {
  return vf(_mm256_round_ps(__m256(x), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
}
[[gnu::always_inline]] inline vf permv(vf table, vu idx) {
  return vf(_mm256_permutevar8x32_ps(__m256(table), __m256i(idx)));
}
[[gnu::always_inline]] inline vf positivev(vf x) { return vf(_mm256_max_ps(__m256(x), _mm256_setzero_ps())); }
#include "noise/basis_simd_rows.inc"
}  // namespace simd_avx2
#if defined(__clang__)
#pragma clang attribute pop
#pragma clang attribute push(__attribute__((target("avx512f,avx512vl,avx512bw,avx512dq"))), apply_to = function)
#else
#pragma GCC pop_options
#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512bw,avx512dq")
#endif
namespace simd_avx512 {
constexpr int W = 16;
typedef float vf __attribute__((vector_size(64)));
typedef int32_t vi __attribute__((vector_size(64)));
typedef uint32_t vu __attribute__((vector_size(64)));
[[gnu::always_inline]] inline vf loadu(const float* p) { return vf(_mm512_loadu_ps(p)); }
[[gnu::always_inline]] inline void storeu(float* p, vf x) { _mm512_storeu_ps(p, __m512(x)); }
[[gnu::always_inline]] inline vf floorv(vf x) {
  return vf(_mm512_roundscale_ps(__m512(x), _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC));
}
[[gnu::always_inline]] inline vf permv(vf table, vu idx) {
  return vf(_mm512_permutexvar_ps(__m512i(idx), __m512(table)));
}
[[gnu::always_inline]] inline vf positivev(vf x) { return vf(_mm512_max_ps(__m512(x), _mm512_setzero_ps())); }
#include "noise/basis_simd_rows.inc"
}  // namespace simd_avx512
#if defined(__clang__)
#pragma clang attribute pop
#else
#pragma GCC pop_options
#endif

}  // namespace ft::noise::detail
