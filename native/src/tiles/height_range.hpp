// SPDX-License-Identifier: GPL-3.0-or-later
// The one height scale of a tile set: every 16-bit tile maps the same
// [min, max] to 0..65535, so neighbouring tiles give their shared edge
// samples the same 16-bit values. The range must hold every sample of the
// whole terrain, which never exists in memory; it comes from
//
//  - midpoint (plain, periodic, or a reference grid of at most the coarse
//    pass's levels with reference_scale 'sigma'): a bound. The terrain's
//    stage m = min(levels, 12) is generated whole (at most 4097^2 samples: its
//    every 2^(levels - m)-th sample, exactly, as windows at that lod are the
//    coarser stage); each later half-step k places points at the mean of
//    points already placed plus delta_k g, delta_k = sigma 2^(-k H / 2), and a
//    mean never leaves the range of what it averages, so every sample lies
//    within the coarse range widened by G sum_{k > 2m} delta_k, where
//    G = 5.9 bounds |g|: the Box-Muller variates are sqrt(-2 ln u) times a
//    sine or cosine with u >= 2^-25 (rng.hpp), so |g| <= sqrt(50 ln 2) =
//    5.888. A relative 1e-5 is added for float rounding. With levels <= 12 the
//    pass is the whole terrain and the range is exact.
//  - mandelbrot: [0, sigma], the range of its height formula (terrain.h).
//  - every other method (additions move old points at every stage, fbm and
//    interpolated have no cheap coarse stage): exact, by generating every
//    tile once before writing (generation costs twice).
//  - an eroded terrain: exact, by building every tile once before writing;
//    what is built is kept for the writing pass (tile_writer.hpp), so
//    erosion runs once per tile.
#pragma once

#include <string>

#include "terrain/terrain.hpp"  // ft_terrain_params
#include "tiles/tile_grid.hpp"
#include "tiles/tile_writer.hpp"

namespace ft::tiles {

struct HeightRange {
  double min = 0, max = 0;
  std::string how;  // "exact", "bound" or "formula", for the manifest
};

// The range of set `spec` of terrain `t` in folder `dir` (where an eroded
// set's range pass keeps its tiles).
HeightRange tileset_height_range(const TileTerrain& t, const TileSpec& spec, const std::string& dir);
// A generated terrain's (never eroded: no folder needed).
HeightRange tileset_height_range(const ft_terrain_params& p, const TileGrid& grid);

// Whether the range comes from the exact pass over every tile (the last two
// cases above), and that pass's unit of work: one tile's exact range, which
// any process can compute (Dask runs one task per tile; the union is the
// set's). An eroded set's unit (build_pending_tile) keeps the tile in `dir`.
bool needs_exact_pass(const ft_terrain_params& p);
bool needs_exact_pass(const TileTerrain& t);
HeightRange tile_height_range(const ft_terrain_params& p, const TileGrid& grid, int32_t col, int32_t row);
HeightRange tile_height_range(const TileTerrain& t, const TileSpec& spec, const std::string& dir, int32_t col,
                              int32_t row);

// The widening of the bound above after coarse stage m of a midpoint terrain
// of `levels` levels: 5.9 sum_{k = 2m + 1}^{2 levels} sigma 2^(-k H / 2).
double midpoint_bound_margin(int levels, int m, double hurst, double sigma);

}  // namespace ft::tiles
