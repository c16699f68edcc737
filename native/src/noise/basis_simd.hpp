// The value and gradient bases of flat, non-periodic fbm written with
// explicit AVX2 and AVX-512 vectors (the octave loop's hottest rows), for
// the dispatch paths of fbm.cpp. They perform the same IEEE operations in
// the same order as basis.hpp's sample-at-a-time code, so every path gives
// the same bits; what they save is work that is not arithmetic on the
// result: floor by one rounding instruction instead of a conversion round
// trip, the gradient of a corner by two register permutes instead of
// selects and sign flips, and the v-products of a row computed once.
#pragma once

#include "noise/octave.hpp"

namespace ft::noise::detail {

// noise(M (u, v) + o) for the n <= 256 samples at u[i], v[i] into out[i],
// as basis.hpp's value_noise / gradient_noise<false> give them. v_const:
// every v[i] equals v[0] (a row without warp). Call only where the CPU has
// the instruction set (fbm.cpp's dispatch).
void value_row_avx2(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out);
void gradient_row_avx2(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out);
void value_row_avx512(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out);
void gradient_row_avx512(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out);

}  // namespace ft::noise::detail
