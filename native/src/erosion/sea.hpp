// SPDX-License-Identifier: GPL-3.0-or-later
// The sea, for erosion and for the rivers (hydrology/ uses these). Erosion
// takes every cell at or below the sea's level as a base level like the
// map's edge (erode.cpp): rivers end there, the sediment that reaches it is
// carried away, and the sea floor stays as it is. Without this an eroded
// island's flat sea (the landform's) took the sediment of every river as
// deposit and rose into sand flats and specks (issue 24). The rivers take
// only the part connected to the map's edge as sea (sea_cells); an enclosed
// basin below the level is a lake to them.
#pragma once

#include <cstdint>
#include <vector>

#include "core/heightfield.hpp"
#include "erosion/d8_grid.hpp"

namespace ft::erosion {

// Where the sea is: the values of FT_WATER_SEA_* (hydrology.h), the same as
// the landform's FT_SEA_* (terrain.h).
enum class Sea : int32_t { kNone = 0, kHeight = 1, kFraction = 2 };

// The sea's height: `level` (kHeight), the sample with `fraction` of the
// samples below it (kFraction: the landform's convention, terrain/landform.cpp
// apply_sea, so a terrain made with sea fraction F and its erosion and rivers
// with sea fraction F agree), or NaN (kNone, or an empty terrain).
double sea_height(Sea sea, double level, double fraction, const Heightfield& hf);

// A sample at or below the sea's level, compared as floats: the landform
// flattens its sea to float(level), which lies above a level such as 0.1
// that rounds up, and a double comparison then finds no sea at all. False
// for a NaN level.
inline bool in_sea(float z, double level) { return z <= float(level); }

// 1 for the sea's cells: at or below `level` (a landform's sea is flat at
// exactly its level) and connected, 8-neighbour, to the map's edge (periodic:
// to the lowest sample) through such cells. An enclosed depression below
// the level is not sea (a lake). All 0 for a level that is not finite.
std::vector<uint8_t> sea_cells(const D8Grid& g, const float* z, double level);

}  // namespace ft::erosion
