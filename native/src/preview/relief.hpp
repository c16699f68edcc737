// SPDX-License-Identifier: GPL-3.0-or-later
// Shaded-relief previews of heightfields: a hypsometric tint (sea, sand,
// grass, rock, snow by altitude) lit by a low sun from the north-west, the
// way cartographers draw relief. For looking at terrains without a renderer.
#pragma once

#include <cstdint>
#include <vector>

#include "core/heightfield.hpp"

namespace ft::preview {

struct ReliefOptions {
  double sea_fraction = 0.35;   // fraction of the height range under water (0 = no sea)
  double exaggeration = 0;   // vertical exaggeration; 0 picks one from the data
  double sun_azimuth = 315;  // degrees clockwise from north (image up)
  double sun_elevation = 40;  // degrees above the horizon
};

// Returns width * height * 3 bytes of RGB, row 0 first.
std::vector<uint8_t> shaded_relief(const Heightfield& hf, const ReliefOptions& options);

}  // namespace ft::preview
