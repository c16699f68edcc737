// SPDX-License-Identifier: GPL-3.0-or-later
// The angular power spectrum of a planet's heights and H from its slope.
//
// An isotropic field on the sphere h = sum a_lm Y_lm has the angular power
// spectrum C_l = sum_m |a_lm|^2 / (2l + 1), and its variogram is
//   2 gamma(theta) = E[(h(p) - h(q))^2] = sum_l (2l + 1) / (2 pi) C_l (1 - P_l(cos theta)).
// For C_l = c l^-a with 2 < a < 4 and small theta, 1 - P_l(cos theta) ~
// 1 - J0(l theta) (Hilb's formula), and with l theta = u the sum becomes
//   (c / pi) theta^(a - 2) integral u^(1 - a) (1 - J0(u)) du,
// which converges at both ends for 2 < a < 4: gamma ~ theta^(a - 2). fBm's
// gamma ~ theta^(2H) gives a = 2H + 2, the exponent of the flat radial
// spectrum P(k) ~ k^-(2H + 2) of a surface (l is k at one radius).
//
// No library: Debian 12 has no SHTns, and its libsharp (1.0, GPL-2, HEALPix's)
// would add a dependency the Windows build lacks for a transform that is
// small here: a direct one up to degree 512. Heights on a Gauss-Legendre grid
// of 4 (lmax + 1) rings of 8 (lmax + 1) points (4 times oversampled, so
// power above the fitted degrees aliases little), a plain DFT of each ring
// for m <= lmax, and the fully normalised associated Legendre functions by
// the standard three-term recurrence in l (stable for every m; the
// sectoral start sin^m theta underflows only where it is below 1e-300).
#pragma once

#include <array>
#include <vector>

#include "planet/planet.hpp"

namespace ft::planet {

inline constexpr int kMaxSpectrumDegree = 512;

// The Gauss-Legendre grid of degree lmax: ring k at cos theta = x[k]
// (north first), point j at longitude 2 pi j / nlon.
struct ShGrid {
  explicit ShGrid(int lmax);
  int lmax, nlat, nlon;
  std::vector<double> x, w;
  std::array<double, 3> direction(int k, int j) const;
};
// C_l, l = 0..lmax, of the grid's values h (nlat rows of nlon, row k ring k).
std::vector<double> power_spectrum(const ShGrid& grid, const float* h, int threads);

// C_l for l = 0..lmax (2..kMaxSpectrumDegree) of the heights, sea applied
// (a midpoint planet's interpolated from the cube-sphere level whose spacing
// is at most the grid's, cube_sampler.hpp). Progress and cancel.
std::vector<double> angular_power_spectrum(const Planet& planet, int lmax);

struct SpectrumHurst {
  double hurst = 0, std_error = 0;  // H = (-slope - 2) / 2 and the slope's standard error / 2
  double slope = 0;
  int l_min = 0, l_max = 0;
};
// The least-squares slope of log C_l against log l over l_min..l_max
// (1 <= l_min < l_max < power.size()).
SpectrumHurst spectrum_hurst(const std::vector<double>& power, int l_min, int l_max);

}  // namespace ft::planet
