// basis_simd.hpp's rows: basis_simd_rows.inc compiled once for AVX2 and
// once for AVX-512 (512-bit vectors), each in its own target region.
#include "noise/basis_simd.hpp"

#include <immintrin.h>

#include <cstdint>

#include "noise/basis.hpp"

// gcc 12 warns inside its own AVX-512 headers once they are inlined.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace ft::noise::detail {

#pragma GCC push_options
#pragma GCC target("avx2")
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
#include "noise/basis_simd_rows.inc"
}  // namespace simd_avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f,avx512vl,avx512bw,avx512dq")
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
#include "noise/basis_simd_rows.inc"
}  // namespace simd_avx512
#pragma GCC pop_options

void value_row_avx2(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out) {
  simd_avx2::value_row(o, n, u, v, v_const, out);
}
void gradient_row_avx2(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out) {
  simd_avx2::gradient_row(o, n, u, v, v_const, out);
}
void value_row_avx512(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out) {
  simd_avx512::value_row(o, n, u, v, v_const, out);
}
void gradient_row_avx512(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out) {
  simd_avx512::gradient_row(o, n, u, v, v_const, out);
}

}  // namespace ft::noise::detail
