// SPDX-License-Identifier: GPL-3.0-or-later
// Lake shorelines: marching squares (contour/) at the lake's level less the
// minimum depth over the lake's cells and their neighbours, so the line runs
// where the water becomes that deep, between samples (at the level itself a
// hollow filled to a plain's height would have its shoreline, and water
// flush with the ground, all over the plain). Every neighbour of a lake cell is at or
// above the level (a lower one would have drained it), so the field outside
// that ring can be anything above the level.
//
// On a periodic grid a lake may cross the seam: its cells are unwrapped
// first (walked from one cell, each step keeping its unwrapped offset, as the
// rivers are), so its box is the lake's own and its rings are closed lines
// whose coordinates may leave [0, period) like the rivers'. (Cut by the seam
// instead, such a lake had open chains and no ring at all.)
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "contour/marching_squares.hpp"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {
namespace {

// The cells of every lake with unwrapped positions (x, y may leave the grid
// on a periodic one), lake by lake in index order.
struct LakeCells {
  std::vector<std::vector<std::array<int32_t, 2>>> cells;
};

LakeCells unwrapped_cells(const erosion::D8Grid& g, const Water& water) {
  LakeCells out;
  out.cells.resize(water.lakes.size());
  std::vector<uint8_t> seen(g.size(), 0);
  std::vector<std::array<int32_t, 2>> todo;
  for (size_t s = 0; s < g.size(); ++s) {
    const int32_t l = water.label[s];
    if (l < 0 || seen[s]) continue;
    auto& cells = out.cells[size_t(l)];
    seen[s] = 1;
    todo.assign(1, {int32_t(s % size_t(g.width)), int32_t(s / size_t(g.width))});
    while (!todo.empty()) {
      const auto [ux, uy] = todo.back();
      todo.pop_back();
      cells.push_back({ux, uy});
      const int32_t x = ((ux % g.width) + g.width) % g.width, y = ((uy % g.height) + g.height) % g.height;
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(x, y, k);
        if (j < 0 || seen[size_t(j)] || water.label[size_t(j)] != l) continue;
        seen[size_t(j)] = 1;
        todo.push_back({ux + erosion::kDx[k], uy + erosion::kDy[k]});
      }
    }
  }
  return out;
}

}  // namespace

PolylineSet lake_rings(const erosion::D8Grid& g, const float* z, Water& water) {
  const int32_t nl = int32_t(water.lakes.size());
  const LakeCells lakes = unwrapped_cells(g, water);
  PolylineSet out;
  for (int32_t l = 0; l < nl; ++l) {
    Lake& lake = water.lakes[size_t(l)];
    lake.first_ring = out.line_count();
    const auto& cells = lakes.cells[size_t(l)];
    int32_t bx0 = INT32_MAX, by0 = INT32_MAX, bx1 = INT32_MIN, by1 = INT32_MIN;
    for (const auto& [x, y] : cells)
      bx0 = std::min(bx0, x), by0 = std::min(by0, y), bx1 = std::max(bx1, x), by1 = std::max(by1, y);
    // A lake that wraps all the way around the torus has no inside to draw.
    if (bx1 - bx0 + 3 > g.width + (g.periodic ? 0 : 2) || by1 - by0 + 3 > g.height + (g.periodic ? 0 : 2)) {
      lake.ring_count = 0;
      continue;
    }
    // One sample of margin (a lake never touches a bounded map's edge: the
    // edge drains it).
    const int32_t x0 = g.periodic ? bx0 - 1 : std::max(0, bx0 - 1), y0 = g.periodic ? by0 - 1 : std::max(0, by0 - 1);
    const int32_t x1 = g.periodic ? bx1 + 1 : std::min(g.width - 1, bx1 + 1);
    const int32_t y1 = g.periodic ? by1 + 1 : std::min(g.height - 1, by1 + 1);
    const int32_t bw = x1 - x0 + 1, bh = y1 - y0 + 1;
    // The lake's cells and their 8-neighbours in the box keep their heights;
    // the rest is dry land above the level.
    std::vector<uint8_t> near(size_t(bw) * bh, 0);
    for (const auto& [x, y] : cells)
      for (int32_t dy = -1; dy <= 1; ++dy)
        for (int32_t dx = -1; dx <= 1; ++dx) {
          const int32_t bx = x + dx - x0, by = y + dy - y0;
          if (bx >= 0 && by >= 0 && bx < bw && by < bh) near[size_t(by) * bw + bx] = 1;
        }
    const float level = float(lake.level), dry = std::nextafter(level, INFINITY) + 1.0f;
    Heightfield f(bw, bh);
    for (int32_t by = 0; by < bh; ++by)
      for (int32_t bx = 0; bx < bw; ++bx) {
        const int32_t x = ((bx + x0) % g.width + g.width) % g.width, y = ((by + y0) % g.height + g.height) % g.height;
        f.at(bx, by) = near[size_t(by) * bw + bx] ? z[size_t(y) * g.width + x] : dry;
      }
    // Where the water is min_depth deep: every lake cell lies deeper, every
    // other cell near it shallower (or dry), so the rings close around the
    // lake's cells and the ground inside lies under the level by more.
    const PolylineSet chains = contour::marching_squares(f, double(level) - water.min_depth);
    // Closed loops, largest shoreline first, then the islands.
    std::vector<std::tuple<int, double, int64_t>> loops;
    for (int64_t i = 0; i < chains.line_count(); ++i) {
      const contour::ChainKind kind = contour::chain_kind(chains, i);
      if (kind == contour::ChainKind::kOpen) continue;
      const double a = contour::signed_area(chains, i);
      loops.push_back({kind == contour::ChainKind::kLake ? 0 : 1, -std::fabs(a), i});  // shorelines first, largest first
    }
    std::sort(loops.begin(), loops.end());
    for (const auto& [group, size, i] : loops) {
      for (int64_t v = chains.line_begin(i); v < chains.line_end(i); ++v) {
        const Vec3& p = chains.points[size_t(v)];
        out.add({(p[0] + x0) * g.spacing, (p[1] + y0) * g.spacing, lake.level});
      }
      out.end_line();
    }
    lake.ring_count = out.line_count() - lake.first_ring;
    lake.outer_rings = std::count_if(loops.begin(), loops.end(), [](const auto& l) { return std::get<0>(l) == 0; });
  }
  return out;
}

}  // namespace ft::hydrology
