// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/spectral_synthesis.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace ft::terrain {
namespace {

// FFTW's planner is not thread-safe; execution of a plan is.
std::mutex g_fftw_planner;

struct FftwFree {
  void operator()(void* p) const { fftwf_free(p); }
};
template <class T>
using FftwBuffer = std::unique_ptr<T, FftwFree>;

// The plan is destroyed on every path, including a cancellation between
// planning and execution (the planner lock covers destruction too).
struct PlanDeleter {
  void operator()(fftwf_plan_s* plan) const {
    std::lock_guard<std::mutex> lock(g_fftw_planner);
    fftwf_destroy_plan(plan);
  }
};
using Plan = std::unique_ptr<fftwf_plan_s, PlanDeleter>;

template <class T>
FftwBuffer<T> fftw_alloc(size_t count) {
  T* p = static_cast<T*>(fftwf_malloc(sizeof(T) * count));
  if (!p) fail(FT_ERR_OUT_OF_MEMORY, "out of memory for the spectral synthesis buffers");
  return FftwBuffer<T>(p);
}

// A coefficient's wave: kx cycles across the width and ky across the height,
// i.e. (kx L / w, ky L / h) cycles across the longer side L = max(w, h). The
// same wave at every size of the same shape, so its random coefficient and
// its amplitude are functions of (kx, ky) alone: a larger terrain holds the
// same waves and adds finer ones.
struct Waves {
  double sx, sy;  // L / w, L / h
  Waves(int32_t w, int32_t h) : sx(double(std::max(w, h)) / w), sy(double(std::max(w, h)) / h) {}
  double f2(int64_t kx, int64_t ky) const { return (kx * sx) * (kx * sx) + (ky * sy) * (ky * sy); }
};

// The Philox row of wave number ky, signed: 0, -1, 1, -2, 2, ... at rows 0,
// 1, 2, 3, 4, ... (a row index of the FFT array, ky + h for ky < 0, would
// move with h).
uint32_t wave_row(int32_t ky) { return ky >= 0 ? uint32_t(2 * int64_t(ky)) : uint32_t(-2 * int64_t(ky) - 1); }

// The power E sum |X|^2 of the unscaled amplitudes f^-(H + 1) over the
// reference band: every nonzero wave (kx, ky) of the whole plane with both
// |kx L / w| and |ky L / h| <= kSpectralReferenceWaves, each contributing 2 f^-(2H + 2)
// (its Re and Im). Those are the waves of a 512-sample-wide terrain; sigma^2
// is their variance at every size.
double reference_power(int32_t w, int32_t h, double hurst) {
  const int64_t l = std::max(w, h);
  const int64_t kx_max = kSpectralReferenceWaves * int64_t(w) / l, ky_max = kSpectralReferenceWaves * int64_t(h) / l;
  const Waves waves(w, h);
  double sum = 0;
  for (int64_t ky = 0; ky <= ky_max; ++ky)
    for (int64_t kx = ky == 0 ? 1 : 0; kx <= kx_max; ++kx)
      sum += (kx > 0 ? 2.0 : 1.0) * (ky > 0 ? 2.0 : 1.0) * 2.0 * std::pow(waves.f2(kx, ky), -(hurst + 1.0));
  return sum;
}

}  // namespace

double spectral_power_ratio_bound(int32_t w, int32_t h, double hurst) {
  // The grid's waves inside the band are among the reference's; each of the
  // fewer than w h outside it has f > kSpectralReferenceWaves, so E|X|^2 below
  // 2 kSpectralReferenceWaves^-(2H + 2).
  const double outside = 2.0 * double(w) * double(h) * std::pow(double(kSpectralReferenceWaves), -2.0 * (hurst + 1.0));
  return 1.0 + outside / reference_power(w, h, hurst);
}

Heightfield spectral_synthesis(const SpectralConfig& c) {
  const int32_t w = c.width, h = c.height, hw = w / 2 + 1;
  const size_t ncoef = size_t(h) * size_t(hw);
  check_allocation(checked_bytes(ncoef, 2 * sizeof(float)) + checked_bytes(size_t(w), size_t(h), 2 * sizeof(float)),
                   "spectral synthesis of a " + std::to_string(w) + " x " + std::to_string(h) + " terrain");
  auto coef = fftw_alloc<fftwf_complex>(ncoef);
  auto real = fftw_alloc<float>(size_t(w) * size_t(h));
  Plan plan;
  {
    std::lock_guard<std::mutex> lock(g_fftw_planner);
    // FFTW_ESTIMATE: the plan (and so every bit of the output) does not
    // depend on timing measurements, and the arrays are not touched.
    plan.reset(fftwf_plan_dft_c2r_2d(h, w, coef.get(), real.get(), FFTW_ESTIMATE));
  }
  if (!plan) fail(FT_ERR_INTERNAL, "FFTW could not plan a " + std::to_string(w) + " x " + std::to_string(h) + " c2r transform");

  // Coefficient (kx, ky) (ky above h / 2 stands for ky - h): Re and Im are
  // independent N(0, 1) from Philox at (wave_row(ky), index 2 kx), times
  // scale f^-(H + 1) with f in cycles across the longer side: a uniform
  // random phase and a Rayleigh amplitude, the same for the same wave at any
  // size. FFTW's c2r is unnormalised, so a coefficient adds the same wave to
  // every size's samples. The scale makes the reference band's variance
  // sigma^2 (reference_power): a world constant, never the grid's own sum,
  // which grows with the finer waves of a larger grid.
  const double exponent = -0.5 * (c.hurst + 1.0);  // applied to f^2
  const double scale = c.sigma / std::sqrt(reference_power(w, h, c.hurst));
  const Waves waves(w, h);
  const int threads = resolve_threads(c.threads);
  float* base = &coef.get()[0][0];
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int32_t row_index = 0; row_index < h; ++row_index) {
    const int32_t ky = row_index <= h / 2 ? row_index : row_index - h;
    float* row = base + size_t(row_index) * hw * 2;
    gaussian_fill(c.seed, Counter{wave_row(ky), 0, Stream::kSpectral}, 0, size_t(hw) * 2, row);
    for (int32_t kx = 0; kx < hw; ++kx) {
      const double f2 = waves.f2(kx, ky);
      const float amp = float(f2 > 0 ? scale * std::pow(f2, exponent) : 0.0);
      row[2 * kx] *= amp;
      row[2 * kx + 1] *= amp;
    }
  }
  // Columns kx = 0 and (w even) kx = w / 2 hold their own mirror images:
  // Hermitian symmetry X(-ky) = conj X(ky) there, and real values where
  // ky = -ky (ky = 0, and h / 2 when h is even). Elsewhere c2r supplies the
  // mirror half itself.
  auto coef_at = [&](int32_t kx, int32_t ky) { return base + (size_t(ky) * hw + kx) * 2; };
  for (int32_t kx : {0, w % 2 == 0 ? w / 2 : -1}) {
    if (kx < 0) continue;
    for (int32_t ky = h / 2 + 1; ky < h; ++ky) {
      const float* m = coef_at(kx, h - ky);
      float* x = coef_at(kx, ky);
      x[0] = m[0];
      x[1] = -m[1];
    }
    coef_at(kx, 0)[1] = 0.0f;
    if (h % 2 == 0) coef_at(kx, h / 2)[1] = 0.0f;
  }
  c.progress.report(0.5);

  fftwf_execute(plan.get());
  plan.reset();
  Heightfield hf(w, h);
  std::copy(real.get(), real.get() + size_t(w) * size_t(h), hf.data());
  c.progress.report(1.0);
  return hf;
}

}  // namespace ft::terrain
