// SPDX-License-Identifier: GPL-3.0-or-later
// Power-spectrum slope through FFTW: every transect is detrended (least-
// squares line: removes the mean and the wrap-around jump that would leak a
// f^-2 spectrum), Hann-windowed, transformed; the periodograms are summed,
// averaged in log-spaced bins (8 per octave) and fitted over the band.
#include <fftw3.h>

#include <cmath>
#include <memory>
#include <mutex>

#include "analysis/hurst.hpp"
#include "core/error.hpp"

namespace ft::analysis::detail {
namespace {

// FFTW's planner is not thread-safe; execution of a plan is.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}

struct FftwFree {
  void operator()(void* p) const { fftw_free(p); }
};

constexpr size_t kBlock = 32;  // transects per partial sum: fixed, so sums do not depend on threads

}  // namespace

void add_periodograms(const float* v, size_t n, ptrdiff_t stride, size_t count, ptrdiff_t step, double* power) {
  const size_t half = n / 2;
  fftw_plan plan;
  {
    std::unique_ptr<double, FftwFree> in(fftw_alloc_real(n));
    std::unique_ptr<fftw_complex, FftwFree> out(fftw_alloc_complex(half + 1));
    std::lock_guard<std::mutex> lock(planner_mutex());
    plan = fftw_plan_dft_r2c_1d(int(n), in.get(), out.get(), FFTW_ESTIMATE);
  }
  if (!plan) fail(FT_ERR_INTERNAL, "FFTW could not plan a transform of " + std::to_string(n) + " samples");
  std::vector<double> window(n);
  double wsum2 = 0;
  for (size_t i = 0; i < n; ++i) {
    window[i] = 0.5 - 0.5 * std::cos(2.0 * M_PI * double(i) / double(n));
    wsum2 += window[i] * window[i];
  }
  // Least-squares line: centred abscissa u_i = i - (n - 1) / 2.
  const double uc = 0.5 * double(n - 1);
  double suu = 0;
  for (size_t i = 0; i < n; ++i) suu += (double(i) - uc) * (double(i) - uc);

  const size_t blocks = (count + kBlock - 1) / kBlock;
  std::vector<double> partial(blocks * (half + 1), 0.0);
#pragma omp parallel
  {
    std::unique_ptr<double, FftwFree> in(fftw_alloc_real(n));
    std::unique_ptr<fftw_complex, FftwFree> out(fftw_alloc_complex(half + 1));
#pragma omp for schedule(dynamic, 1)
    for (size_t b = 0; b < blocks; ++b) {
      double* acc = partial.data() + b * (half + 1);
      for (size_t t = b * kBlock; t < std::min(count, (b + 1) * kBlock); ++t) {
        const float* p = v + ptrdiff_t(t) * step;
        double mean = 0, suy = 0;
        for (size_t i = 0; i < n; ++i) mean += p[ptrdiff_t(i) * stride];
        mean /= double(n);
        for (size_t i = 0; i < n; ++i) suy += (double(i) - uc) * (p[ptrdiff_t(i) * stride] - mean);
        const double slope = suy / suu;
        double* x = in.get();
        for (size_t i = 0; i < n; ++i) x[i] = (p[ptrdiff_t(i) * stride] - mean - slope * (double(i) - uc)) * window[i];
        fftw_execute_dft_r2c(plan, x, out.get());
        const fftw_complex* X = out.get();
        for (size_t k = 1; k <= half; ++k) acc[k] += (X[k][0] * X[k][0] + X[k][1] * X[k][1]) / wsum2;
      }
    }
  }
  for (size_t b = 0; b < blocks; ++b)
    for (size_t k = 1; k <= half; ++k) power[k] += partial[b * (half + 1) + k];
  std::lock_guard<std::mutex> lock(planner_mutex());
  fftw_destroy_plan(plan);
}

void fit_spectrum(const std::vector<double>& power, Band band, HurstEstimate& e) {
  // Bins [lo 2^(b/8), lo 2^((b+1)/8)): each point is the mean power of the
  // frequencies in it, at the geometric mean of those frequencies.
  constexpr double kPerOctave = 8;
  const size_t half = power.size() - 1;
  e.x.clear(), e.y.clear();
  for (int b = 0;; ++b) {
    const double f0 = band.lo * std::exp2(b / kPerOctave), f1 = band.lo * std::exp2((b + 1) / kPerOctave);
    if (f0 > band.hi) break;
    double logf = 0, p = 0;
    int c = 0;
    for (size_t k = size_t(std::ceil(f0)); double(k) < f1 && double(k) <= band.hi && k <= half; ++k)
      if (k >= 1) logf += std::log(double(k)), p += power[k], ++c;
    if (c > 0) e.x.push_back(std::exp(logf / c)), e.y.push_back(p / c);
  }
  e.fit = fit_loglog(e.x, e.y, "spectral Hurst estimate");
}

}  // namespace ft::analysis::detail
