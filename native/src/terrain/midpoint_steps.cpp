#include "terrain/midpoint_steps.hpp"

namespace ft::detail {
namespace {

// The hot loops. The last stage (stride 2) holds three quarters of all
// points; with the stride known at compile time its loops vectorise (even/odd
// lane shuffles). Compiled for AVX2 and baseline x86-64: the arithmetic of a
// point is the same on every path (no FMA contraction), so are the bits.
template <int kStride>
inline void square_points(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                          float delta, const float* g) {
  const int stride = kStride ? kStride : big, h = kStride ? kStride / 2 : half;
  for (int i = 0; i < count; ++i) {
    const int x = x0 + i * stride;
    row[x] = 0.25f * ((up[x - h] + up[x + h]) + (dn[x - h] + dn[x + h])) + delta * g[i];
  }
}

template <int kStride>
inline void diamond_points(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                           float delta, const float* g) {
  const int stride = kStride ? kStride : big, h = kStride ? kStride / 2 : half;
  for (int i = 0; i < count; ++i) {
    const int x = x0 + i * stride;
    row[x] = 0.25f * ((row[x - h] + row[x + h]) + (up[x] + dn[x])) + delta * g[i];
  }
}

}  // namespace

__attribute__((target_clones("avx2", "default")))
void square_row(float* row, const float* up, const float* dn, int x0, int count, int big, int half, float delta,
                const float* g) {
  if (big == 2) square_points<2>(row, up, dn, x0, count, big, half, delta, g);
  else square_points<0>(row, up, dn, x0, count, big, half, delta, g);
}

__attribute__((target_clones("avx2", "default")))
void diamond_interior(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                      float delta, const float* g) {
  if (big == 2) diamond_points<2>(row, up, dn, x0, count, big, half, delta, g);
  else diamond_points<0>(row, up, dn, x0, count, big, half, delta, g);
}

}  // namespace ft::detail
