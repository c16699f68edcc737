// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/midpoint_steps.hpp"

#include <string_view>

#include "core/kernel_clones.hpp"
#include "core/rng.hpp"

namespace ft::terrain::detail {
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

FT_KERNEL_CLONES_AVX2
void square_row_portable(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                         float delta, const float* g) {
  if (big == 2) square_points<2>(row, up, dn, x0, count, big, half, delta, g);
  else square_points<0>(row, up, dn, x0, count, big, half, delta, g);
}

FT_KERNEL_CLONES_AVX2
void diamond_interior_portable(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                               float delta, const float* g) {
  if (big == 2) diamond_points<2>(row, up, dn, x0, count, big, half, delta, g);
  else diamond_points<0>(row, up, dn, x0, count, big, half, delta, g);
}

// The AVX-512 kernels where the Gaussians take the AVX-512 path too: one
// switch (FT_DISPATCH=avx2 or baseline turns both off).
bool steps_avx512() {
  static const bool yes = std::string_view(ft::detail::dispatch_path()) == "avx512";
  return yes;
}

void square_row(float* row, const float* up, const float* dn, int x0, int count, int big, int half, float delta,
                const float* g) {
  if (steps_avx512_stride(big) && steps_avx512()) square_row_avx512(row, up, dn, x0, count, big, delta, g);
  else square_row_portable(row, up, dn, x0, count, big, half, delta, g);
}

void diamond_interior(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                      float delta, const float* g) {
  if (steps_avx512_stride(big) && steps_avx512()) diamond_interior_avx512(row, up, dn, x0, count, big, delta, g);
  else diamond_interior_portable(row, up, dn, x0, count, big, half, delta, g);
}

}  // namespace ft::terrain::detail
