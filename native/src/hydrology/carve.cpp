// SPDX-License-Identifier: GPL-3.0-or-later
// Carving: each river segment (between two vertices) is a capsule of its
// half width; every cell within it is lowered to the water surface minus
// the depth x cos^2(pi r / 2), r = distance / half width: the full depth on
// the centre line, smoothly (zero slope) back to the surface at the banks.
//
// That profile alone left the ground flush with a narrow river: its banks
// meet the surface, and a river much narrower than a cell lies between
// samples whose triangles span the slope around it, so the ground between
// the samples stood over the ribbon drawn there. So every grid cell the
// ribbon covers (its capsule) also has its four corners lowered under the
// plane that extends the segment's water surface along it (level across
// it) by kRibbonFlat x the half width: the ground is linear on the cell's
// triangles (either split), and so is that plane, so under the whole ribbon
// the ground lies that far under the water.
//
// The result is a minimum over segments, so the order they are drawn in
// does not matter (deterministic on any thread count). Beds never go below
// the sea's level, and sea and lake cells are never lowered.
#include <algorithm>
#include <cmath>

#include "hydrology/hydrology.hpp"

namespace ft::hydrology {
namespace {

// The distance from the segment a + t e (t in [0, 1]) to the square of side
// 2 h centred on c; 0 when they meet.
double segment_square_distance(double ax, double ay, double ex, double ey, double cx, double cy, double h) {
  // Liang-Barsky: does the segment cross the square?
  double t0 = 0, t1 = 1;
  const double p[4] = {-ex, ex, -ey, ey};
  const double q[4] = {ax - (cx - h), (cx + h) - ax, ay - (cy - h), (cy + h) - ay};
  bool inside = true;
  for (int k = 0; k < 4 && inside; ++k) {
    if (p[k] == 0) {
      inside = q[k] >= 0;
    } else {
      const double t = q[k] / p[k];
      if (p[k] < 0) t0 = std::max(t0, t);
      else t1 = std::min(t1, t);
      inside = t0 <= t1;
    }
  }
  if (inside) return 0;
  auto to_square = [&](double x, double y) {
    return std::hypot(std::max(0.0, std::abs(x - cx) - h), std::max(0.0, std::abs(y - cy) - h));
  };
  const double ee = ex * ex + ey * ey;
  auto to_segment = [&](double x, double y) {
    const double t = ee > 0 ? std::clamp(((x - ax) * ex + (y - ay) * ey) / ee, 0.0, 1.0) : 0.0;
    return std::hypot(x - ax - t * ex, y - ay - t * ey);
  };
  double d = std::min(to_square(ax, ay), to_square(ax + ex, ay + ey));
  for (const double sx : {-h, h})
    for (const double sy : {-h, h}) d = std::min(d, to_segment(cx + sx, cy + sy));
  return d;
}

}  // namespace

Heightfield carve(const Heightfield& terrain, const RiverNetwork& net) {
  const erosion::D8Grid& g = net.grid;
  if (terrain.width() != g.width || terrain.height() != g.height)
    invalid("carve: the terrain is " + std::to_string(terrain.width()) + " x " + std::to_string(terrain.height()) +
            " samples, the rivers were made on " + std::to_string(g.width) + " x " + std::to_string(g.height));
  Heightfield out(terrain.width(), terrain.height());
  out.set_world_size(terrain.world_size());
  out.set_georef(terrain.georef());
  std::copy(terrain.data(), terrain.data() + terrain.size(), out.data());
  float* z = out.data();
  // Beds stop at the sea's level: lower, a river's bed near the coast would
  // be a trench of sea floor cut into the land (and the sea's surface,
  // which covers what lies below its level, would fill it).
  const double floor = std::isnan(net.water.sea_level) ? -INFINITY : net.water.sea_level;
  // The sample (x, y) of the unwrapped grid; -1 off a bounded one.
  auto index = [&](int32_t x, int32_t y) -> int64_t {
    if (g.periodic) {
      x = ((x % g.width) + g.width) % g.width;
      y = ((y % g.height) + g.height) % g.height;
    } else if (x < 0 || y < 0 || x >= g.width || y >= g.height) {
      return -1;
    }
    return int64_t(y) * g.width + x;
  };
  auto lower = [&](int64_t i, double bed) {
    if (i >= 0 && net.water.label[size_t(i)] == kLand)  // lakes and the sea keep their level
      z[i] = std::min(z[i], float(std::max(floor, bed)));
  };
  const PolylineSet& L = net.lines;
  for (int64_t line = 0; line < L.line_count(); ++line)
    for (int64_t v = L.line_begin(line); v + 1 < L.line_end(line); ++v) {
      const Vec3 &a = L.points[size_t(v)], &b = L.points[size_t(v + 1)];
      const double ra = L.radii[size_t(v)], rb = L.radii[size_t(v + 1)];
      const double ha = std::max(ra, 0.75 * g.spacing);
      const double hb = std::max(rb, 0.75 * g.spacing);
      const double da = net.depth[size_t(v)], db = net.depth[size_t(v + 1)];
      const double ribbon = std::max(ra, rb), clearance = kRibbonFlat * ribbon;
      const double reach = std::max(std::max(ha, hb), ribbon + g.spacing);
      const int32_t x0 = int32_t(std::floor((std::min(a[0], b[0]) - reach) / g.spacing));
      const int32_t x1 = int32_t(std::ceil((std::max(a[0], b[0]) + reach) / g.spacing));
      const int32_t y0 = int32_t(std::floor((std::min(a[1], b[1]) - reach) / g.spacing));
      const int32_t y1 = int32_t(std::ceil((std::max(a[1], b[1]) + reach) / g.spacing));
      const double ex = b[0] - a[0], ey = b[1] - a[1], ee = ex * ex + ey * ey;
      auto along = [&](double x, double y) {  // t of the point nearest (x, y)
        return ee > 0 ? std::clamp(((x - a[0]) * ex + (y - a[1]) * ey) / ee, 0.0, 1.0) : 0.0;
      };
      for (int32_t y = y0; y <= y1; ++y)
        for (int32_t x = x0; x <= x1; ++x) {
          // The profile, at the sample (x, y).
          const double px = x * g.spacing, py = y * g.spacing;
          const double t = along(px, py);
          const double dist = std::hypot(px - a[0] - t * ex, py - a[1] - t * ey);
          const double h = ha + t * (hb - ha);
          if (dist < h) {
            const double c = std::cos(0.5 * M_PI * dist / h);
            lower(index(x, y), a[2] + t * (b[2] - a[2]) - (da + t * (db - da)) * c * c);
          }
          // The clearance, over the cell (x, y) - (x + 1, y + 1): its corners
          // go under the river's surface extended along the segment (a plane
          // level across it), so the cell's triangles, which interpolate the
          // corners linearly, lie that far under it wherever the ribbon is.
          const double s = 0.5 * g.spacing;
          if (segment_square_distance(a[0], a[1], ex, ey, px + s, py + s, s) >= ribbon) continue;
          for (const int32_t cy : {y, y + 1})
            for (const int32_t cx : {x, x + 1}) {
              // At most one segment's drop past its ends: a segment much shorter
              // than a cell (a steep fall) would otherwise dig a pit beside it.
              const double u = ee > 0 ? std::clamp(((cx * g.spacing - a[0]) * ex + (cy * g.spacing - a[1]) * ey) / ee,
                                                   -1.0, 2.0)
                                      : 0.0;
              lower(index(cx, cy), a[2] + u * (b[2] - a[2]) - clearance);
            }
        }
    }
  return out;
}

}  // namespace ft::hydrology
