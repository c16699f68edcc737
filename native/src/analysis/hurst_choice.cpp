// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/hurst_choice.hpp"

#include <algorithm>

namespace ft::analysis {
namespace {

bool dyadic(int64_t n) { return n >= 3 && ((n - 1) & (n - 2)) == 0; }

}  // namespace

// The dyadic-aligned variogram on 2^n + 1 grids: it uses exactly the pairs
// the midpoint and additions generators displace with variance
// sigma^2 tau^(2H) (Voss 1985), so it is unbiased there. Elsewhere the
// spectral slope once the record holds >= 256 samples (5 octaves in its
// default band [n / 128 .. n / 8] cycles): on spectral-synthesis fields the
// plain variogram's small lags see the spectrum's cut-off at Nyquist and read
// H = 0.3 as 0.38. Below that, the plain variogram, which needs fewest samples.
HurstChoice choose_hurst_method(int64_t width, int64_t height) {
  const bool profile = height <= 1;
  if (profile ? dyadic(width) : dyadic(width) && dyadic(height))
    return {HurstMethod::kVariogramAligned, HurstChoiceReason::kDyadicGrid,
            "2^n + 1 samples per side: the dyadic-aligned variogram is exact for the midpoint and additions "
            "grids"};
  const int64_t shortest = profile ? width : std::min(width, height);
  if (shortest >= 256)
    return {HurstMethod::kSpectral, HurstChoiceReason::kLongRecord,
            "not a 2^n + 1 grid, >= 256 samples per side: the spectral slope (the plain variogram reads low "
            "H too high near Nyquist)"};
  return {HurstMethod::kVariogram, HurstChoiceReason::kShortRecord,
          "not a 2^n + 1 grid, < 256 samples per side: the plain variogram (too short for the spectral band)"};
}

}  // namespace ft::analysis
