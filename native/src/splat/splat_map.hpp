// SPDX-License-Identifier: GPL-3.0-or-later
// Splat (weight) maps and colour maps of a terrain by layer rules
// (fracterra/splat.h says what a rule means). Every sample is computed on its
// own, so the result does not depend on the thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "core/heightfield.hpp"
#include "core/progress.hpp"
#include "fracterra/splat.h"

namespace ft::splat {

// What the rules look at: the terrain and, optionally, two erosion maps of
// its size (deposited thickness in world units, drainage area in world
// units^2; null: their conditions see 0).
// A window's whole terrain (a tile of a tile set): the rules' height fractions
// and flow areas are the whole's, not the window's own.
struct SplatFrame {
  double low = 0, range = 0;  // the whole's lowest height and relief
  double area = 1;            // the whole's area, world units^2
};

struct SplatInputs {
  const Heightfield* terrain = nullptr;
  const Heightfield* deposited = nullptr;
  const Heightfield* drainage_area = nullptr;
  const SplatFrame* frame = nullptr;  // null: the terrain is the whole
};

// The built-in rule set: grass, rock, sediment, snow (R, G, B, A).
std::vector<ft_splat_params> default_layers();

// The band of a rule: 0..1, linear across [edge - blend/2, edge + blend/2]
// at each edge, a hard step for blend 0 (1 inside [lo, hi]).
double band(double x, double lo, double hi, double blend);

// The layers' weights divided by their sum, sample-major (sample i's layers
// at [i * n, (i + 1) * n)); where no layer has weight the first takes it all.
// Validates the layers and the maps' sizes.
std::vector<float> layer_fractions(const SplatInputs& in, const ft_splat_params* layers, int32_t n);

// Rounds one sample's fractions (summing to 1) to integers summing to
// exactly `total`, by largest remainder (ties: the lower layer).
void round_to_total(const float* fractions, int32_t n, int32_t total, uint16_t* out);

// The integer weights of every sample (sample-major), each sample summing to
// `total` (255 or 65535).
std::vector<uint16_t> splat_weights(const SplatInputs& in, const ft_splat_params* layers, int32_t n,
                                    int32_t total);

// sRGB 0..1, three floats per sample: the layers' colours mixed by their fractions.
std::vector<float> splat_colors(const SplatInputs& in, const ft_splat_params* layers, int32_t n);

// The same colours in linear RGB (IEC 61966-2-1 decoding), for renderers that
// light in linear light: the POV-Ray scenes' terrain colours.
std::vector<float> splat_colors_linear(const SplatInputs& in, const ft_splat_params* layers, int32_t n);

// splat_colors_linear's colours with alpha 1, four floats per sample into
// `rgba` (width * height * 4): Blender's colour attribute. Rows in parallel
// on up to `threads` threads (0: all cores), the same bits on any count;
// `progress` hears the share of rows done and may cancel.
void splat_colors_linear_rgba(const SplatInputs& in, const ft_splat_params* layers, int32_t n, int threads,
                              const Progress& progress, float* rgba);

}  // namespace ft::splat
