// SPDX-License-Identifier: GPL-3.0-or-later
// A terrain cut into tiles that share their edge samples: tile (col, row)
// holds the samples [col t, col t + t] x [row t, row t + t] (t = `tile`
// cells, t + 1 samples a side; the last column and row may be narrower), so
// the last sample of a tile is the first of its neighbour and meshes built
// from neighbouring tiles close without cracks. A midpoint terrain of
// 2^n + 1 samples cut with t = 2^k has (2^(n-k))^2 tiles of 2^k + 1 samples.
#pragma once

#include <cstdint>
#include <string>

#include "terrain/window.hpp"

namespace ft::tiles {

struct TileGrid {
  int64_t width = 0, height = 0;  // the whole terrain's samples
  int32_t tile = 0;               // cells per tile side

  int32_t columns() const noexcept { return int32_t((width - 2) / tile + 1); }
  int32_t rows() const noexcept { return int32_t((height - 2) / tile + 1); }
  int64_t count() const noexcept { return int64_t(columns()) * rows(); }
  // The samples of tile (col, row); callers check the indices (check_tile).
  terrain::Window window(int32_t col, int32_t row) const;
  // Throws naming the tile and the grid when (col, row) is outside.
  void check_tile(int32_t col, int32_t row) const;
};

// The grid of a terrain of width x height samples; throws for a tile size
// outside [2, 65536] or more than kMaxTiles tiles.
TileGrid make_tile_grid(int64_t width, int64_t height, int64_t tile);

inline constexpr int64_t kMaxTiles = 1 << 20;

}  // namespace ft::tiles
