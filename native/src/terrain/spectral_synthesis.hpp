// Spectral synthesis of fBm (Saupe's SpectralSynthesisFM in 2D): random
// Fourier coefficients with |amplitude| ~ f^-(H + 1), one inverse real FFT
// (FFTW's c2r). The power spectrum falls as f^-(2H + 2) (rows: f^-(2H + 1)),
// and the result is periodic by construction: it tiles seamlessly.
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "core/progress.hpp"

namespace ft {

struct SpectralConfig {
  int32_t width = 513, height = 513;  // any sizes >= 2
  double hurst = 0.8;                 // [0, 1]
  double sigma = 1.0;                 // expected standard deviation of the result
  uint64_t seed = 1;
  int threads = 0;
  Progress progress;
};

// Callers validate (terrain.cpp). The mean is exactly 0 (no DC term).
Heightfield spectral_synthesis(const SpectralConfig& c);

}  // namespace ft
