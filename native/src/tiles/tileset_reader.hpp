// Reading a window of a finished tile set back from its tile files, at a
// level of detail: sample (i, j) of the result is sample
// ((x0 + i) 2^lod, (y0 + j) 2^lod) of the whole, taken from the tile that
// holds it (16-bit tiles in the set's real units, GeoTIFF tiles exactly).
// For a midpoint terrain every 2^lod-th sample is exactly its coarser stage,
// so a coarse window of a huge set is a true coarser terrain. Only the
// tiles the window touches are read.
#pragma once

#include <cstdint>
#include <string>

#include "core/heightfield.hpp"

namespace ft::tiles {

// The whole set's samples per side at level of detail `lod`:
// (width - 1) / 2^lod + 1 (rounded down).
void tileset_extent(const std::string& dir, int lod, int64_t* width, int64_t* height);

// Throws for a folder without a finished tile set, a window outside the
// extent at that lod, or a tile whose file is missing or damaged (its
// CRC-32 is checked against the manifest). The world size recorded is the
// window's own extent.
Heightfield read_tileset_window(const std::string& dir, int lod, int64_t x0, int64_t y0, int32_t width,
                                int32_t height);

}  // namespace ft::tiles
