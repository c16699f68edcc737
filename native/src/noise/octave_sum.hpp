// SPDX-License-Identifier: GPL-3.0-or-later
// How an octave's noise is added into the running sum, the same for every
// fbm (flat and spherical): one noise call per octave, then the variant's
// way of adding it in (Musgrave's formulations, with a_i = gain^i in place
// of f_i^-H). always_inline, so it is compiled inside each caller's target.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/error.hpp"
#include "noise/fbm.hpp"

namespace ft::noise::detail {

// The octave fields FbmConfig and Fbm3Config share, checked alike (each
// config then checks its own fields: grid size, warp, the lattice's range).
template <class Config>
void validate_octave_fields(const Config& c) {
  check_int_range("octaves", c.octaves, 1, kMaxOctaves);
  if (!(c.lacunarity > 1.0) || !std::isfinite(c.lacunarity))
    invalid("lacunarity must be a finite number > 1 (2 doubles the frequency per octave; 2.01 is a "
            "common choice), got " + format_number(c.lacunarity));
  if (std::isnan(c.gain) || c.gain > 1.0)
    invalid("gain must be in (0, 1] (or <= 0 to use lacunarity^-H), got " + format_number(c.gain));
  check_range("hurst", c.hurst, 0.0, 1.0);
  check_int_range("basis", c.basis, kBasisValue, kBasisCellularF2F1);
  check_int_range("variant", c.variant, kFbmStandard, kFbmHetero);
  check_positive("frequency", c.frequency);
  check_finite("offset", c.offset);
  check_positive("sigma", c.sigma);
}

// sum[i] (and the variant's weight[i]) after adding an octave of amplitude `a`;
// `first` for octave 0.
[[gnu::always_inline]] inline void add_octave(int variant, bool first, float a, float offset, int n,
                                              const float* noise, float* weight, float* sum) {
  switch (variant) {
    case kFbmStandard:
      for (int i = 0; i < n; ++i) sum[i] = first ? a * noise[i] : sum[i] + a * noise[i];
      break;
    case kFbmRidged:  // ridges where the noise crosses zero, sharpened by the octave below
      for (int i = 0; i < n; ++i) {
        const float ab = noise[i] < 0.0f ? -noise[i] : noise[i];
        float s = offset - ab;
        s = s * s;
        s = first ? s : s * weight[i];
        float w = s * 2.0f;
        w = w > 1.0f ? 1.0f : (w < 0.0f ? 0.0f : w);
        weight[i] = w;
        sum[i] = first ? a * s : sum[i] + a * s;
      }
      break;
    case kFbmHybrid:  // detail grows where the terrain is already high
      for (int i = 0; i < n; ++i) {
        const float s = (noise[i] + offset) * a;
        if (first) {
          sum[i] = s;
          weight[i] = s;
        } else {
          const float w = weight[i] > 1.0f ? 1.0f : weight[i];
          sum[i] = sum[i] + w * s;
          weight[i] = w * s;
        }
      }
      break;
    default:  // kFbmHetero: increments scaled by the height so far
      for (int i = 0; i < n; ++i)
        sum[i] = first ? offset + noise[i] : sum[i] + ((noise[i] + offset) * a) * sum[i];
      break;
  }
}

}  // namespace ft::noise::detail
