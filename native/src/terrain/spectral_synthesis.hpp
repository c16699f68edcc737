// SPDX-License-Identifier: GPL-3.0-or-later
// Spectral synthesis of fBm (Saupe's SpectralSynthesisFM in 2D): random
// Fourier coefficients with |amplitude| ~ f^-(H + 1), one inverse real FFT
// (FFTW's c2r). The power spectrum falls as f^-(2H + 2) (rows: f^-(2H + 1)),
// and the result is periodic by construction: it tiles seamlessly.
//
// Resolution independent: a coefficient is keyed, and its amplitude set, by
// its wave number in cycles across the terrain (not per sample), so the same
// seed at 4x the samples holds the same waves and adds finer ones; sampled
// at the smaller grid's points the two agree but for those finer waves
// (tests/native/resolution_test.cpp).
#pragma once

#include <cstdint>

#include "core/heightfield.hpp"
#include "core/progress.hpp"

namespace ft::terrain {

// sigma is the standard deviation of the waves up to this many cycles
// across the longer side (all those of a 512-sample-wide terrain), at every
// size: a larger terrain adds finer waves and a little variance (at 4096
// samples +0.003% of the std at H 0.8, +1% at H 0.3), a smaller one lacks
// some (at 256: -0.007%, -0.7%).
inline constexpr int32_t kSpectralReferenceWaves = 256;

struct SpectralConfig {
  int32_t width = 513, height = 513;  // any sizes >= 2
  double hurst = 0.8;                 // [0, 1]
  double sigma = 1.0;                 // std of the waves up to kSpectralReferenceWaves
  uint64_t seed = 1;
  int threads = 0;
  Progress progress;
};

// Callers validate (terrain.cpp). The mean is exactly 0 (no DC term).
Heightfield spectral_synthesis(const SpectralConfig& c);

// An upper bound of a width x height terrain's expected power over sigma^2
// (>= 1: the waves beyond the reference band add to it), for the float-range
// check of terrain.cpp.
double spectral_power_ratio_bound(int32_t width, int32_t height, double hurst);

}  // namespace ft::terrain
