// SPDX-License-Identifier: GPL-3.0-or-later
// A river's vertices from its cells: the 8-direction staircase smoothed
// away, meanders by Nikulin's FPL (polyline/fpl) between vertices, and every
// vertex kept in its valley. The surface T is the filled terrain (lakes flat
// at their level), read bilinearly. A cell centre's T never rises
// downstream (the receivers descend the graded surface), so the rule
//   a moved vertex v is kept when T(v) <= T(previous kept) + tolerance and
//   T(v) >= T(centre of the next cell), else v falls back to its centre
//   (or, between centres, is dropped)
// keeps the whole line at most `tolerance` above its upstream neighbour at
// every vertex: the next centre always passes after a kept vertex.
#include <algorithm>
#include <cmath>
#include <vector>

#include "hydrology/hydrology.hpp"
#include "polyline/fpl.hpp"

namespace ft::hydrology {

double surface_at(const erosion::D8Grid& g, const std::vector<float>& level, double x, double y) {
  double fx = x / g.spacing, fy = y / g.spacing;
  if (g.periodic) {
    fx -= std::floor(fx / g.width) * g.width;
    fy -= std::floor(fy / g.height) * g.height;
  } else {
    fx = std::clamp(fx, 0.0, double(g.width - 1));
    fy = std::clamp(fy, 0.0, double(g.height - 1));
  }
  int32_t x0 = std::min(int32_t(fx), g.width - 1), y0 = std::min(int32_t(fy), g.height - 1);
  const double tx = fx - x0, ty = fy - y0;
  auto at = [&](int32_t x, int32_t y) {
    if (g.periodic) x %= g.width, y %= g.height;
    else x = std::min(x, g.width - 1), y = std::min(y, g.height - 1);
    return double(level[size_t(y) * g.width + x]);
  };
  // Exact at the samples (tx = 0 takes no weight from the next column).
  double top = at(x0, y0), bottom = at(x0, y0 + 1);
  if (tx > 0) top += tx * (at(x0 + 1, y0) - top), bottom += tx * (at(x0 + 1, y0 + 1) - bottom);
  return ty > 0 ? top + ty * (bottom - top) : top;
}

PathVertices river_path(const erosion::D8Grid& g, const Water& w, const std::vector<int32_t>& cells,
                        const std::vector<std::array<double, 2>>& offsets, const std::vector<double>& half_width,
                        const HydrologyConfig& c, uint32_t line_id) {
  const size_t m = cells.size();
  std::vector<Vec3> centre(m);
  for (size_t k = 0; k < m; ++k)
    centre[k] = {(cells[k] % g.width) * g.spacing + offsets[k][0], (cells[k] / g.width) * g.spacing + offsets[k][1],
                 double(w.level[size_t(cells[k])])};
  // The sea's surface is its level, not its floor.
  if (std::isfinite(w.sea_level) && w.label[size_t(cells.back())] == kSea)
    centre.back()[2] = std::max(centre.back()[2], w.sea_level);
  // 1. Smoothing: passes of (1/4, 1/2, 1/4) with the ends fixed (they are
  //    shared with the neighbouring segments).
  std::vector<Vec3> smooth = centre, next = centre;
  for (int32_t pass = 0; pass < c.smoothing; ++pass) {
    for (size_t k = 1; k + 1 < m; ++k)
      for (int d = 0; d < 2; ++d) next[k][d] = 0.25 * smooth[k - 1][d] + 0.5 * smooth[k][d] + 0.25 * smooth[k + 1][d];
    smooth.swap(next);
  }
  auto surface = [&](const Vec3& p) { return surface_at(g, w.level, p[0], p[1]); };
  PathVertices out;
  out.points.push_back(centre[0]);
  out.source.push_back(0);
  for (size_t k = 1; k < m; ++k) {
    Vec3 v = centre[k];
    if (k + 1 < m) {
      Vec3 s = smooth[k];
      s[2] = surface(s);
      const double prev = out.points.back()[2];
      if (s[2] <= prev + c.tolerance && s[2] >= centre[k + 1][2]) v = s;
    } else if (w.label[size_t(cells[k])] == kSea) {
      v[2] = std::min(v[2], out.points.back()[2]);  // the sea's level may sit above a low last cell
    }
    out.points.push_back(v);
    out.source.push_back(int32_t(k));
  }
  if (c.meander_depth <= 0) return out;

  // 2. Meanders: an FPL between each pair of vertices, its sideways
  //    excursion scaled to at most the river's width there; a vertex that
  //    would climb out of the valley is dropped.
  PathVertices meandered;
  polyline::FplConfig f;
  f.spread = c.meander_spread;
  f.depth = c.meander_depth;
  f.seed = c.seed;
  f.threads = 1;
  std::vector<Vec3> fpl;
  for (size_t k = 0; k + 1 < out.points.size(); ++k) {
    const Vec3 a = out.points[k], b = out.points[k + 1];
    meandered.points.push_back(a);
    meandered.source.push_back(out.source[k]);
    const uint32_t id = line_id * 2654435761u + uint32_t(k);
    fpl.resize(size_t(polyline::fpl_vertex_count(f, {a[0], a[1], 0}, {b[0], b[1], 0}, id)));
    polyline::fpl_segment(f, {a[0], a[1], 0}, {b[0], b[1], 0}, id, fpl.data());
    const double dx = b[0] - a[0], dy = b[1] - a[1], len = std::hypot(dx, dy);
    if (len <= 0) continue;
    double largest = 0;
    for (const Vec3& p : fpl) largest = std::max(largest, std::fabs((p[0] - a[0]) * dy - (p[1] - a[1]) * dx) / len);
    const double limit = 2.0 * half_width[size_t(out.source[k])];
    const double scale = largest > limit ? limit / largest : 1.0;
    for (size_t j = 1; j + 1 < fpl.size(); ++j) {
      // Along the chord as the FPL put it, sideways scaled.
      const double along = ((fpl[j][0] - a[0]) * dx + (fpl[j][1] - a[1]) * dy) / (len * len);
      const double side = ((fpl[j][0] - a[0]) * -dy + (fpl[j][1] - a[1]) * dx) / len * scale;
      Vec3 p{a[0] + along * dx - side * dy / len, a[1] + along * dy + side * dx / len, 0};
      p[2] = surface(p);
      if (p[2] <= meandered.points.back()[2] + c.tolerance && p[2] >= b[2]) {
        meandered.points.push_back(p);
        meandered.source.push_back(out.source[k]);
      }
    }
  }
  meandered.points.push_back(out.points.back());
  meandered.source.push_back(out.source.back());
  return meandered;
}

}  // namespace ft::hydrology
