// SPDX-License-Identifier: GPL-3.0-or-later
// Carving: each river segment (between two vertices) is a capsule of its
// half width; every cell within it is lowered to the water surface minus
// the depth x cos^2(pi r / 2), r = distance / half width: the full depth on
// the centre line, smoothly (zero slope) back to the surface at the banks.
// The result is a minimum over segments, so the order they are drawn in
// does not matter (deterministic on any thread count). Beds never go below
// the sea's level, and sea and lake cells are never lowered.
#include <algorithm>
#include <cmath>

#include "hydrology/hydrology.hpp"

namespace ft::hydrology {

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
  const PolylineSet& L = net.lines;
  for (int64_t line = 0; line < L.line_count(); ++line)
    for (int64_t v = L.line_begin(line); v + 1 < L.line_end(line); ++v) {
      const Vec3 &a = L.points[size_t(v)], &b = L.points[size_t(v + 1)];
      const double ha = std::max(L.radii[size_t(v)], 0.75 * g.spacing);
      const double hb = std::max(L.radii[size_t(v + 1)], 0.75 * g.spacing);
      const double da = net.depth[size_t(v)], db = net.depth[size_t(v + 1)];
      const double reach = std::max(ha, hb);
      const int32_t x0 = int32_t(std::floor((std::min(a[0], b[0]) - reach) / g.spacing));
      const int32_t x1 = int32_t(std::ceil((std::max(a[0], b[0]) + reach) / g.spacing));
      const int32_t y0 = int32_t(std::floor((std::min(a[1], b[1]) - reach) / g.spacing));
      const int32_t y1 = int32_t(std::ceil((std::max(a[1], b[1]) + reach) / g.spacing));
      const double ex = b[0] - a[0], ey = b[1] - a[1], ee = ex * ex + ey * ey;
      for (int32_t y = y0; y <= y1; ++y)
        for (int32_t x = x0; x <= x1; ++x) {
          int32_t cx = x, cy = y;
          if (g.periodic) {
            cx = ((x % g.width) + g.width) % g.width;
            cy = ((y % g.height) + g.height) % g.height;
          } else if (x < 0 || y < 0 || x >= g.width || y >= g.height) {
            continue;
          }
          const size_t i = size_t(cy) * g.width + cx;
          if (net.water.label[i] != kLand) continue;  // lakes and the sea keep their level
          const double px = x * g.spacing - a[0], py = y * g.spacing - a[1];
          const double t = ee > 0 ? std::clamp((px * ex + py * ey) / ee, 0.0, 1.0) : 0.0;
          const double dist = std::hypot(px - t * ex, py - t * ey);
          const double h = ha + t * (hb - ha);
          if (dist >= h) continue;
          const double surface = a[2] + t * (b[2] - a[2]);
          const double c = std::cos(0.5 * M_PI * dist / h);
          const double bed = std::max(floor, surface - (da + t * (db - da)) * c * c);
          z[i] = std::min(z[i], float(bed));
        }
    }
  return out;
}

}  // namespace ft::hydrology
