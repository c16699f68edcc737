// SPDX-License-Identifier: GPL-3.0-or-later
// Iterated function systems by random iteration (seed 002): affine maps
//   x' = a x + b y + e,   y' = c x + d y + f,
// one chosen at each step with probability p. The tables given in seed 002:
// Barnsley's fern (4 maps) and the Harter-Heighway dragon and Koch curve
// coded on a 640 x 350 screen (2 and 4 maps, equal probabilities); and the
// Sierpinski gasket of its text (3 maps of ratio 1/2, D = log 3 / log 2).
#pragma once

#include <cstdint>
#include <vector>

#include "core/polyline_set.hpp"
#include "core/progress.hpp"

namespace ft::polyline {

struct IfsMap {
  double a, b, c, d, e, f, p;
};

// The built-in tables. Their values are the ABI's FT_IFS_* (polyline.cpp
// checks this at compile time), so ft_polyline_params.ifs_preset passes on
// unchanged while this algorithm does not include the public header.
enum IfsPreset : int32_t { kIfsFern = 0, kIfsDragon = 1, kIfsKoch = 2, kIfsSierpinskiGasket = 3 };

// The table of a preset; throws FT_ERR_INVALID_ARGUMENT for any other value.
std::vector<IfsMap> ifs_preset(int preset);
// Checks a table: 1..64 maps, finite coefficients, p >= 0 with a positive sum.
void validate_ifs(const std::vector<IfsMap>& maps);

// `count` attractor points from the origin after 64 discarded steps; the map
// of step k is chosen by index k of Counter{0, 0, Stream::kIfs}. One
// single-vertex line per point (z = 0, radius 0). Throws if the orbit
// diverges (a map that is not contractive).
PolylineSet ifs_points(const std::vector<IfsMap>& maps, int64_t count, uint64_t seed,
                       const Progress& progress = {});

}  // namespace ft::polyline
