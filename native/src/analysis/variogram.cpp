// SPDX-License-Identifier: GPL-3.0-or-later
// Variogram and madogram over a band of lags, plain or dyadic-aligned, for
// profiles and surfaces. Partial sums are kept per row and added in row
// order, so the result does not depend on the thread count.
#include <cmath>

#include "analysis/hurst.hpp"
#include "core/error.hpp"

namespace ft::analysis {
namespace {

bool aligned(HurstMethod m) {
  return m == HurstMethod::kVariogramAligned || m == HurstMethod::kMadogramAligned;
}
bool squares(HurstMethod m) { return m == HurstMethod::kVariogram || m == HurstMethod::kVariogramAligned; }

// The statistic of one increment: half its square (semi-variogram) or its
// absolute value (madogram).
inline double term(double d, bool sq) { return sq ? 0.5 * d * d : std::fabs(d); }

// Adds the statistic of the increments v[i + tau] - v[i] of one transect.
// Aligned: i runs over multiples of tau only.
void transect_sum(const float* v, size_t n, ptrdiff_t stride, int64_t tau, bool al, bool sq, double& sum,
                  double& count) {
  const size_t step = al ? size_t(tau) : 1;
  double s = 0;
  size_t c = 0;
  for (size_t i = 0; i + size_t(tau) < n; i += step, ++c)
    s += term(double(v[ptrdiff_t(i + tau) * stride]) - double(v[ptrdiff_t(i) * stride]), sq);
  sum += s;
  count += double(c);
}

}  // namespace

namespace detail {

void add_increments(const float* v, size_t n, ptrdiff_t stride, HurstMethod m, const std::vector<int64_t>& lags,
                    double* sum, double* count) {
  for (size_t k = 0; k < lags.size(); ++k) transect_sum(v, n, stride, lags[k], aligned(m), squares(m), sum[k], count[k]);
}

// Surfaces: increments along x within rows and along y within columns,
// pooled (the estimator of an isotropic surface). Aligned: only rows and
// columns of the tau grid, only pairs of its nodes.
void surface_increments(const Heightfield& hf, HurstMethod m, const std::vector<int64_t>& lags,
                        std::vector<double>& stat) {
  const int64_t w = hf.width(), h = hf.height();
  const bool al = aligned(m), sq = squares(m);
  stat.assign(lags.size(), 0.0);
  std::vector<double> row_sum(static_cast<size_t>(h)), row_count(static_cast<size_t>(h));
  for (size_t k = 0; k < lags.size(); ++k) {
    const int64_t tau = lags[k];
    const int64_t step = al ? tau : 1;
#pragma omp parallel for schedule(dynamic, 8)
    for (int64_t j = 0; j < h; ++j) {
      double s = 0, c = 0;
      if (j % step == 0) {
        const float* row = hf.data() + j * w;
        if (tau < w) transect_sum(row, size_t(w), 1, tau, al, sq, s, c);
        if (j + tau < h) {  // y increments between row j and row j + tau
          const float* next = row + tau * w;
          double sy = 0;
          int64_t cy = 0;
          for (int64_t i = 0; i < w; i += step, ++cy) sy += term(double(next[i]) - double(row[i]), sq);
          s += sy, c += double(cy);
        }
      }
      row_sum[size_t(j)] = s, row_count[size_t(j)] = c;
    }
    double s = 0, c = 0;
    for (int64_t j = 0; j < h; ++j) s += row_sum[size_t(j)], c += row_count[size_t(j)];
    stat[k] = c > 0 ? s / c : 0.0;
  }
}

}  // namespace detail

}  // namespace ft::analysis
