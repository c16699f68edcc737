// SPDX-License-Identifier: GPL-3.0-or-later
// Thermal erosion (Musgrave, Kolb & Mace 1989): where the drop to a
// neighbour exceeds the talus slope, material slides down. Each pass every
// cell works out, from the previous heights, how much it sends: `rate` x
// half its largest excess drop (half: moving more would turn the step the
// other way), shared among the lower neighbours in proportion to their
// excess. The receivers then gather what their neighbours send, so the pass
// is Jacobi-ordered (thread-count independent) and conserves material to
// rounding; nothing crosses a bounded edge. (talus[k] is the same in both
// directions of a pair, so one table serves sender and receiver.)
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <utility>

#include "core/buffer.hpp"
#include "core/kernel_clones.hpp"
#include "erosion/erosion.hpp"

namespace ft::erosion {
namespace {

// The two halves of a pass on cells x0 .. x1 - 1 of a row that have all
// eight neighbours at the fixed offsets `off` (`i` = row + x). Restrict
// parameters of functions that are not inlined (GCC keeps restrict only on
// parameters): the loops then vectorise, and are built for AVX-512, AVX2
// and the baseline (the same bits on each, as in hydraulic.cpp).
[[gnu::noinline]] FT_KERNEL_CLONES void shares_interior(const float* __restrict z, float* __restrict share, int64_t row, int32_t x0,
                                       int32_t x1, const int64_t* off, const float* talus, float half_rate) {
  const int64_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  const float t[8] = {talus[0], talus[1], talus[2], talus[3], talus[4], talus[5], talus[6], talus[7]};
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    float total = 0.0f, largest = 0.0f;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      const float excess = std::max(0.0f, z[i] - z[i + o[k]] - t[k]);
      total += excess;
      largest = std::max(largest, excess);
    }
    // (total 0: largest is 0 too, and the share 0.)
    share[i] = half_rate * largest / std::max(total, FLT_MIN);
  }
}

[[gnu::noinline]] FT_KERNEL_CLONES void moves_interior(const float* __restrict z, const float* __restrict share,
                                      float* __restrict next, int64_t row, int32_t x0, int32_t x1, const int64_t* off,
                                      const float* talus) {
  const int64_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  const float t[8] = {talus[0], talus[1], talus[2], talus[3], talus[4], talus[5], talus[6], talus[7]};
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    float sent = 0.0f, received = 0.0f;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      const int64_t j = i + o[k];
      sent += std::max(0.0f, z[i] - z[j] - t[k]);
      received += share[j] * std::max(0.0f, z[j] - z[i] - t[k]);
    }
    next[i] = z[i] - share[i] * sent + received;
  }
}

// The same at a cell on the first or last row or column (neighbours -1
// outside a bounded grid).
void shares_edge(const D8Grid& g, const float* z, float* share, int32_t x, int32_t y, const float* talus,
                 float half_rate) {
  const int64_t i = int64_t(y) * g.width + x;
  float total = 0.0f, largest = 0.0f;
  for (int k = 0; k < 8; ++k) {
    const int64_t j = g.neighbour(x, y, k);
    if (j < 0) continue;
    const float excess = std::max(0.0f, z[i] - z[j] - talus[k]);
    total += excess;
    largest = std::max(largest, excess);
  }
  share[i] = half_rate * largest / std::max(total, FLT_MIN);
}

void moves_edge(const D8Grid& g, const float* z, const float* share, float* next, int32_t x, int32_t y,
                const float* talus) {
  const int64_t i = int64_t(y) * g.width + x;
  float sent = 0.0f, received = 0.0f;
  for (int k = 0; k < 8; ++k) {
    const int64_t j = g.neighbour(x, y, k);
    if (j < 0) continue;
    sent += std::max(0.0f, z[i] - z[j] - talus[k]);
    received += share[j] * std::max(0.0f, z[j] - z[i] - talus[k]);
  }
  next[i] = z[i] - share[i] * sent + received;
}

// Row y: `interior(row, x0, x1, off)` where all eight neighbours are at
// fixed offsets, `edge(x)` elsewhere.
template <class Interior, class Edge>
void each_in_row(const D8Grid& g, int32_t y, Interior&& interior, Edge&& edge) {
  const int32_t w = g.width;
  if (y == 0 || y == g.height - 1) {  // outside, or (periodic) wrapped: no fixed offsets
    for (int32_t x = 0; x < w; ++x) edge(x);
    return;
  }
  int64_t off[8];
  for (int k = 0; k < 8; ++k) off[k] = kDy[k] * int64_t(w) + kDx[k];
  edge(0);
  interior(int64_t(y) * w, 1, w - 1, off);
  edge(w - 1);
}

}  // namespace

void thermal(const D8Grid& g, float* z, const ThermalConfig& c, const Progress& progress) {
  const size_t n = g.size();
  const int32_t h = g.height;
  float talus[8];
  for (int k = 0; k < 8; ++k) talus[k] = float(std::tan(c.talus_degrees * M_PI / 180.0) * g.distance(k));
  const float half_rate = float(c.rate) * 0.5f;
  // share[i]: what cell i sends per unit of excess drop (0: nothing). The
  // passes alternate between z and `spare` (huge pages, first touched by
  // the team), and the result is copied to z once if it ends in `spare`.
  Buffer<float> share(n), spare(n);
  const int64_t cells = int64_t(n);
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < cells; ++i) share[i] = spare[i] = 0.0f;
  float* cur = z;
  float* next = spare.data();
  for (int32_t it = 0; it < c.iterations; ++it) {
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      each_in_row(
          g, y,
          [&](int64_t row, int32_t x0, int32_t x1, const int64_t* off) {
            shares_interior(cur, share.data(), row, x0, x1, off, talus, half_rate);
          },
          [&](int32_t x) { shares_edge(g, cur, share.data(), x, y, talus, half_rate); });
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      each_in_row(
          g, y,
          [&](int64_t row, int32_t x0, int32_t x1, const int64_t* off) {
            moves_interior(cur, share.data(), next, row, x0, x1, off, talus);
          },
          [&](int32_t x) { moves_edge(g, cur, share.data(), next, x, y, talus); });
    std::swap(cur, next);
    progress.report(double(it + 1) / c.iterations);
  }
  if (cur != z) {
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < cells; ++i) z[i] = cur[i];
  }
}

}  // namespace ft::erosion
