// SPDX-License-Identifier: GPL-3.0-or-later
// square_row and diamond_interior at strides 2, 4 and 8 (the last three
// stages: 63/64 of all points) written for AVX-512; midpoint_steps.cpp takes
// them where the CPU has it. Lanes are grid places x .. x + 15, the points
// every stride-th lane: masked loads read just the points' neighbours
// (nothing past the row's last one, so no scalar tail) and a masked store
// writes just the points. gcc's own AVX2 loop spends a permute per load and
// 8 extracts per 8 stores on stride 2, and does not vectorise wider strides. Same arithmetic in the same order as
// midpoint_steps.cpp (no FMA: -ffp-contract=off), so the same bits; tests
// compare the two.
#include <immintrin.h>

#include "core/avx512.hpp"
#include "terrain/midpoint_steps.hpp"

namespace ft::terrain::detail {
namespace {

// Lanes 0, S, 2 S, ...: the first `points` (<= 16 / S) points of a group.
template <int S>
FT_AVX512 __mmask16 points_mask(int points) {
  uint32_t m = 0;
  for (int k = 0; k < 16 / S; ++k) m |= 1u << (k * S);
  return __mmask16(m & ((1u << (S * (points - 1) + 1)) - 1u));
}

// g[0 .. points) spread so that lane k S holds g[k].
template <int S>
FT_AVX512 __m512 spread_draws(const float* g, int points) {
  const __m256 v = _mm256_maskz_loadu_ps(__mmask8((1u << points) - 1u), g);
  return _mm512_permutexvar_ps(_mm512_setr_epi32(0 / S, 1 / S, 2 / S, 3 / S, 4 / S, 5 / S, 6 / S, 7 / S, 8 / S,
                                                 9 / S, 10 / S, 11 / S, 12 / S, 13 / S, 14 / S, 15 / S),
                               _mm512_castps256_ps512(v));
}

// One group of points: 0.25 ((a + b) + (c + d)) + delta g in the order of
// midpoint_steps.cpp; square: a, b = up[x -+ h], c, d = dn[x -+ h]; diamond:
// a, b = row[x -+ h], c = up[x], d = dn[x].
template <int S, bool kDiamond>
FT_AVX512 __m512 group(const float* row, const float* up, const float* dn, int x, __mmask16 m, __m512 delta,
                       const float* g, int points) {
  constexpr int h = S / 2;
  const float* a = kDiamond ? row + x - h : up + x - h;
  const float* b = kDiamond ? row + x + h : up + x + h;
  const float* c = kDiamond ? up + x : dn + x - h;
  const float* d = kDiamond ? dn + x : dn + x + h;
  const __m512 ab = _mm512_add_ps(_mm512_maskz_loadu_ps(m, a), _mm512_maskz_loadu_ps(m, b));
  const __m512 cd = _mm512_add_ps(_mm512_maskz_loadu_ps(m, c), _mm512_maskz_loadu_ps(m, d));
  return _mm512_add_ps(_mm512_mul_ps(_mm512_set1_ps(0.25f), _mm512_add_ps(ab, cd)),
                       _mm512_mul_ps(delta, spread_draws<S>(g, points)));
}

// A group's loads come before the store of the group before it: a diamond
// group reads the place just past the previous group's store (its points'
// shared neighbour, never written), and a load overlapping a pending
// masked store waits for it to reach the cache (at stride 2 that doubled
// the kernel's time). Points never read other points of the same call, so
// the order changes nothing.
template <int S, bool kDiamond>
__attribute__((target("avx512f,avx512vl,avx512bw,avx512dq"))) void points(float* row, const float* up,
                                                                          const float* dn, int x0, int count,
                                                                          float delta, const float* g) {
  constexpr int P = 16 / S;
  if (count <= 0) return;
  const __m512 d = _mm512_set1_ps(delta);
  int n = count < P ? count : P;
  __mmask16 m = points_mask<S>(n);
  __m512 v = group<S, kDiamond>(row, up, dn, x0, m, d, g, n);
  for (int i = P; i < count; i += P) {
    const int n_next = count - i < P ? count - i : P;
    const __mmask16 m_next = points_mask<S>(n_next);
    const __m512 v_next = group<S, kDiamond>(row, up, dn, x0 + S * i, m_next, d, g + i, n_next);
    _mm512_mask_storeu_ps(row + x0 + S * (i - P), m, v);
    v = v_next, m = m_next;
  }
  _mm512_mask_storeu_ps(row + x0 + S * ((count - 1) / P * P), m, v);
}

}  // namespace

bool steps_avx512_stride(int big) { return big == 2 || big == 4 || big == 8; }

void square_row_avx512(float* row, const float* up, const float* dn, int x0, int count, int big, float delta,
                       const float* g) {
  if (big == 2) points<2, false>(row, up, dn, x0, count, delta, g);
  else if (big == 4) points<4, false>(row, up, dn, x0, count, delta, g);
  else points<8, false>(row, up, dn, x0, count, delta, g);
}

void diamond_interior_avx512(float* row, const float* up, const float* dn, int x0, int count, int big, float delta,
                             const float* g) {
  if (big == 2) points<2, true>(row, up, dn, x0, count, delta, g);
  else if (big == 4) points<4, true>(row, up, dn, x0, count, delta, g);
  else points<8, true>(row, up, dn, x0, count, delta, g);
}

}  // namespace ft::terrain::detail
