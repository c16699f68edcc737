// Lake shorelines: marching squares (contour/) at the lake's level over the
// lake's cells and their neighbours, so the line runs where the terrain
// meets the water, between samples. Every neighbour of a lake cell is at or
// above the level (a lower one would have drained it), so the field outside
// that ring can be anything above the level.
#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

#include "contour/marching_squares.hpp"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {

PolylineSet lake_rings(const erosion::D8Grid& g, const float* z, Water& water) {
  const int32_t nl = int32_t(water.lakes.size());
  // Bounding boxes of the lakes' cells.
  std::vector<std::array<int32_t, 4>> box(size_t(nl), {g.width, g.height, -1, -1});
  for (int32_t y = 0; y < g.height; ++y)
    for (int32_t x = 0; x < g.width; ++x) {
      const int32_t l = water.label[size_t(y) * g.width + x];
      if (l < 0) continue;
      auto& b = box[size_t(l)];
      b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
    }
  PolylineSet out;
  for (int32_t l = 0; l < nl; ++l) {
    Lake& lake = water.lakes[size_t(l)];
    lake.first_ring = out.line_count();
    const auto& b = box[size_t(l)];
    // One sample of margin (a lake never touches a bounded map's edge: the
    // edge drains it).
    const int32_t x0 = std::max(0, b[0] - 1), y0 = std::max(0, b[1] - 1);
    const int32_t x1 = std::min(g.width - 1, b[2] + 1), y1 = std::min(g.height - 1, b[3] + 1);
    const float level = float(lake.level), dry = std::nextafter(level, INFINITY) + 1.0f;
    Heightfield f(x1 - x0 + 1, y1 - y0 + 1);
    for (int32_t y = y0; y <= y1; ++y)
      for (int32_t x = x0; x <= x1; ++x) {
        bool near = false;
        for (int k = -1; k < 8 && !near; ++k) {
          const int64_t j = k < 0 ? int64_t(y) * g.width + x : g.neighbour(x, y, k);
          near = j >= 0 && water.label[size_t(j)] == l;
        }
        f.at(x - x0, y - y0) = near ? z[size_t(y) * g.width + x] : dry;
      }
    const PolylineSet chains = contour::marching_squares(f, double(level));
    // Closed loops only (a lake across a periodic map's seam is cut open by
    // its box: it has no ring), largest shoreline first, then the islands.
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
  }
  return out;
}

}  // namespace ft::hydrology
