#include "terrain/spectral_synthesis.hpp"

#include <fftw3.h>

#include <cmath>
#include <memory>
#include <mutex>
#include <string>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace ft {
namespace {

// FFTW's planner is not thread-safe; execution of a plan is.
std::mutex g_fftw_planner;

struct FftwFree {
  void operator()(void* p) const { fftwf_free(p); }
};
template <class T>
using FftwBuffer = std::unique_ptr<T, FftwFree>;

template <class T>
FftwBuffer<T> fftw_alloc(size_t count) {
  T* p = static_cast<T*>(fftwf_malloc(sizeof(T) * count));
  if (!p) fail(FT_ERR_OUT_OF_MEMORY, "out of memory for the spectral synthesis buffers");
  return FftwBuffer<T>(p);
}

// Destroys the plan on every way out: a cancel from the progress callback
// throws between planning and execution (LeakSanitizer found the plan lost).
struct PlanGuard {
  fftwf_plan plan = nullptr;
  ~PlanGuard() {
    if (!plan) return;
    std::lock_guard<std::mutex> lock(g_fftw_planner);
    fftwf_destroy_plan(plan);
  }
};

}  // namespace

Heightfield spectral_synthesis(const SpectralConfig& c) {
  const int32_t w = c.width, h = c.height, hw = w / 2 + 1;
  const size_t ncoef = size_t(h) * size_t(hw);
  check_allocation(checked_bytes(ncoef, 2 * sizeof(float)) + checked_bytes(size_t(w), size_t(h), 2 * sizeof(float)),
                   "spectral synthesis of a " + std::to_string(w) + " x " + std::to_string(h) + " terrain");
  auto coef = fftw_alloc<fftwf_complex>(ncoef);
  auto real = fftw_alloc<float>(size_t(w) * size_t(h));
  PlanGuard plan;
  {
    std::lock_guard<std::mutex> lock(g_fftw_planner);
    // FFTW_ESTIMATE: the plan (and so every bit of the output) does not
    // depend on timing measurements, and the arrays are not touched.
    plan.plan = fftwf_plan_dft_c2r_2d(h, w, coef.get(), real.get(), FFTW_ESTIMATE);
  }
  if (!plan.plan) fail(FT_ERR_INTERNAL, "FFTW could not plan a " + std::to_string(w) + " x " + std::to_string(h) + " c2r transform");

  // Coefficient (kx, ky): wave numbers kx / w and ky / h cycles per sample
  // (ky above h / 2 stands for ky - h). Re and Im are independent N(0, 1)
  // times f^-(H + 1): a uniform random phase and a Rayleigh amplitude. The
  // two Gaussians come from Philox at (row ky, index 2 kx), so the spectrum
  // is a function of the seed alone.
  const double exponent = -0.5 * (c.hurst + 1.0);  // applied to f^2
  const int threads = resolve_threads(c.threads);
  float* base = &coef.get()[0][0];
#pragma omp parallel for schedule(static) num_threads(threads)
  for (int32_t ky = 0; ky < h; ++ky) {
    float* row = base + size_t(ky) * hw * 2;
    gaussian_fill(c.seed, Counter{uint32_t(ky), 0, Stream::kSpectral}, 0, size_t(hw) * 2, row);
    const double fy = double(ky <= h / 2 ? ky : ky - h) / h;
    for (int32_t kx = 0; kx < hw; ++kx) {
      const double fx = double(kx) / w, f2 = fx * fx + fy * fy;
      const float amp = f2 > 0 ? float(std::pow(f2, exponent)) : 0.0f;
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
  // Expected variance of the output = sum over the full spectrum of
  // E|X|^2 (FFTW's c2r is unnormalised): 2 amp^2 per complex coefficient,
  // amp^2 per real one; the half spectrum stands for both halves except in
  // the self-mirrored columns. Scale to sigma^2, independently of the draws.
  double total = 0;
  for (int32_t ky = 0; ky < h; ++ky) {
    const double fy = double(ky <= h / 2 ? ky : ky - h) / h;
    const bool real_row = ky == 0 || (h % 2 == 0 && ky == h / 2);
    for (int32_t kx = 0; kx < hw; ++kx) {
      const double fx = double(kx) / w, f2 = fx * fx + fy * fy;
      if (f2 == 0) continue;
      const bool mirrored = kx == 0 || (w % 2 == 0 && kx == w / 2);
      const double a2 = std::pow(f2, 2 * exponent);
      total += (mirrored ? 1.0 : 2.0) * (mirrored && real_row ? 1.0 : 2.0) * a2;
    }
  }
  const float scale = float(c.sigma / std::sqrt(total));
  for (size_t i = 0; i < 2 * ncoef; ++i) base[i] *= scale;
  c.progress.report(0.5);

  fftwf_execute(plan.plan);
  Heightfield hf(w, h);
  std::copy(real.get(), real.get() + size_t(w) * size_t(h), hf.data());
  c.progress.report(1.0);
  return hf;
}

}  // namespace ft
