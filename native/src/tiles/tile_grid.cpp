// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/tile_grid.hpp"

#include <algorithm>

#include "core/error.hpp"

namespace ft::tiles {

terrain::Window TileGrid::window(int32_t col, int32_t row) const {
  terrain::Window w;
  w.x0 = int64_t(col) * tile;
  w.y0 = int64_t(row) * tile;
  w.width = int32_t(std::min<int64_t>(tile + 1, width - w.x0));
  w.height = int32_t(std::min<int64_t>(tile + 1, height - w.y0));
  return w;
}

void TileGrid::check_tile(int32_t col, int32_t row) const {
  if (col < 0 || row < 0 || col >= columns() || row >= rows())
    invalid("tile (column " + std::to_string(col) + ", row " + std::to_string(row) + ") is outside the " +
            std::to_string(columns()) + " x " + std::to_string(rows()) + " tile grid");
}

TileGrid make_tile_grid(int64_t width, int64_t height, int64_t tile) {
  check_int_range("tile", tile, 2, 65536);
  if (width < 2 || height < 2) invalid("a tile set needs a terrain of at least 2 x 2 samples");
  TileGrid g{width, height, int32_t(tile)};
  if (g.count() > kMaxTiles)
    invalid("a tile size of " + std::to_string(tile) + " cuts the " + std::to_string(width) + " x " +
            std::to_string(height) + " terrain into " + std::to_string(g.count()) + " tiles; at most " +
            std::to_string(kMaxTiles) + " are allowed: choose a larger --tile");
  return g;
}

}  // namespace ft::tiles
