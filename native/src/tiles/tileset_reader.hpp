// SPDX-License-Identifier: GPL-3.0-or-later
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
#include <vector>

#include "core/heightfield.hpp"
#include "splat/splat_map.hpp"  // ft_splat_params

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
// The same window of map `map` (a kMapNames name) of a set with maps (float32,
// exact); throws for a set without maps.
Heightfield read_tileset_map_window(const std::string& dir, const std::string& map, int lod, int64_t x0, int64_t y0,
                                    int32_t width, int32_t height);
// The whole set at level of detail `lod` as one heightfield, georeferenced in
// the set's map coordinates (sample (x, y) at (x s, -y s)), for what needs the
// whole at once (rivers); refused, naming the lod that fits, when it would
// not fit in memory.
Heightfield read_tileset_whole(const std::string& dir, int lod);

// Whether the finished set in `dir` holds its maps.
bool tileset_has_maps(const std::string& dir);

// The colours of splat rules `layers` (splat/splat_map.hpp) over a window of
// the set at a level of detail, in linear RGBA (4 floats per sample, rows as
// the window's), as those of the whole: the rules see the whole's height
// range and area, the deposits and flow of its maps (a set without maps: none),
// and slopes taken across the window's edges (it is read with one sample of
// margin where the set has one).
std::vector<float> tileset_window_colors(const std::string& dir, int lod, int64_t x0, int64_t y0, int32_t width,
                                         int32_t height, const ft_splat_params* layers, int32_t layer_count);

}  // namespace ft::tiles
