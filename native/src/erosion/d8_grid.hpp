// SPDX-License-Identifier: GPL-3.0-or-later
// The raster seen by the erosion layer: D8 neighbourhoods on a width x height
// grid of square cells `spacing` world units apart, either bounded (the edge
// cells are the outlets: water and sediment leave there) or periodic (a
// torus: every cell has eight neighbours, and one declared sink is the
// outlet), and either way the sea's cells when a sea is given. Heights are in world units too, so slopes are rise over run.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace ft::erosion {

// D8 directions in a fixed order (east, then clockwise in image rows: y grows
// downwards). Opposite of k is (k + 4) % 8.
inline constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
inline constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};

struct D8Grid {
  int32_t width = 0, height = 0;
  bool periodic = false;
  double spacing = 1.0;  // world units between neighbouring samples along x or y
  // Null, or 1 per sea cell (erosion/sea.hpp): base levels besides the
  // edge (or a periodic grid's sink), whose heights no process changes.
  const uint8_t* sea = nullptr;

  size_t size() const { return size_t(width) * size_t(height); }
  double distance(int k) const { return (k & 1) ? spacing * M_SQRT2 : spacing; }
  bool on_edge(int32_t x, int32_t y) const {
    return x == 0 || y == 0 || x == width - 1 || y == height - 1;
  }
  // Calls f(i) for each cell on the edge, row by row.
  template <class F>
  void for_each_edge_cell(F f) const {
    for (int32_t y = 0; y < height; ++y) {
      const int32_t step = (y == 0 || y == height - 1 || width < 2) ? 1 : width - 1;
      for (int32_t x = 0; x < width; x += step) f(size_t(y) * size_t(width) + size_t(x));
    }
  }
  bool in_sea(size_t i) const { return sea && sea[i]; }
  // A base level: water and sediment leave the grid there (receiver = itself).
  bool is_base(int32_t i, int32_t x, int32_t y, int32_t sink) const {
    return (periodic ? i == sink : on_edge(x, y)) || in_sea(size_t(i));
  }
  bool is_base(int32_t i, int32_t sink) const { return is_base(i, i % width, i / width, sink); }
  // Index of neighbour k of (x, y), or -1 outside a bounded grid.
  int64_t neighbour(int32_t x, int32_t y, int k) const {
    int32_t nx = x + kDx[k], ny = y + kDy[k];
    if (periodic) {
      nx = nx < 0 ? nx + width : (nx >= width ? nx - width : nx);
      ny = ny < 0 ? ny + height : (ny >= height ? ny - height : ny);
    } else if (nx < 0 || ny < 0 || nx >= width || ny >= height) {
      return -1;
    }
    return int64_t(ny) * width + nx;
  }
};

}  // namespace ft::erosion
