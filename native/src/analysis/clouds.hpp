// SPDX-License-Identifier: GPL-3.0-or-later
// Feder's clouds (seed 001, fig. 13.13): the landscape thresholded at a
// level; below it black, above it a grey scale from black to white
// proportional to the logarithm of the elevation:
//   grey = ln(e / e_T) / ln(e_max / e_T),  e = h - h_min (elevation above the
//   lowest sample), e_T = threshold - h_min, e_max = h_max - h_min.
// When the threshold is at or below the lowest sample, e_T is taken as 1e-3
// of the range, so the log stays finite. The image is a plain grey PNG
// (row 0 = heightfield row 0), usable as a POV-Ray image_map or a Blender
// image texture.
#pragma once

#include "analysis/quantile.hpp"
#include "core/gray_image.hpp"
#include "core/heightfield.hpp"

namespace ft::analysis {

struct CloudOptions {
  LevelSpec threshold{0.5, true};  // default: the median
  int bit_depth = 8;               // 8 or 16
};

// Samples must be finite. A threshold at or above the highest sample gives an
// all-black image (not an error).
GrayImage clouds_image(const Heightfield& hf, const CloudOptions& options);

}  // namespace ft::analysis
