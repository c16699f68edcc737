// SPDX-License-Identifier: GPL-3.0-or-later
// Per edge of a line, in the edge's own frame (t along it in [0, 1], s across
// it in radii): a ring edge is a segment there, and the ribbon meets it at
// the t where that segment lies within |s| <= 1; between those t, the ribbon
// is all in or all out of the water, as its centre is. The wet t are cut out.
// Where a line turns, its ribbon's cross-section (square to the mean of the
// two edges, as Blender's curve and river_ribbons draw it) sweeps a disc of
// its radius about the point: a part does not pass a point whose disc is wet.
#include "contour/ribbon_clip.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace ft::contour {
namespace {

struct Ring {
  int64_t begin, end;  // vertices of `rings`
  double x0, y0, x1, y1;
};

// Even-odd: is (x, y) inside the rings?
bool inside(const PolylineSet& rings, const std::vector<Ring>& boxes, double x, double y) {
  bool in = false;
  for (const Ring& b : boxes) {
    if (x < b.x0 || x > b.x1 || y < b.y0 || y > b.y1) continue;
    for (int64_t i = b.begin, j = b.end - 1; i < b.end; j = i++) {
      const Vec3 &p = rings.points[size_t(i)], &q = rings.points[size_t(j)];
      if ((p[1] > y) != (q[1] > y) && x < q[0] + (y - q[1]) * (p[0] - q[0]) / (p[1] - q[1])) in = !in;
    }
  }
  return in;
}

// Does the disc of radius r about (x, y) reach into the rings (an edge within r, or inside)?
bool disc_wet(const PolylineSet& rings, const std::vector<Ring>& boxes, double x, double y, double r) {
  for (const Ring& b : boxes) {
    if (x < b.x0 - r || x > b.x1 + r || y < b.y0 - r || y > b.y1 + r) continue;
    for (int64_t i = b.begin, j = b.end - 1; i < b.end; j = i++) {
      const Vec3 &p = rings.points[size_t(j)], &q = rings.points[size_t(i)];
      const double ex = q[0] - p[0], ey = q[1] - p[1], ee = ex * ex + ey * ey;
      const double t = ee > 0 ? std::clamp(((x - p[0]) * ex + (y - p[1]) * ey) / ee, 0.0, 1.0) : 0.0;
      if (std::hypot(x - p[0] - t * ex, y - p[1] - t * ey) <= r) return true;
    }
  }
  return inside(rings, boxes, x, y);
}

}  // namespace

PolylineSet clip_ribbons(const PolylineSet& lines, const PolylineSet& rings, double flat) {
  std::vector<Ring> boxes;
  for (int64_t k = 0; k < rings.line_count(); ++k) {
    Ring b{rings.line_begin(k), rings.line_end(k), INFINITY, INFINITY, -INFINITY, -INFINITY};
    if (b.end - b.begin < 3) continue;
    for (int64_t i = b.begin; i < b.end; ++i) {
      const Vec3& p = rings.points[size_t(i)];
      b.x0 = std::min(b.x0, p[0]), b.y0 = std::min(b.y0, p[1]), b.x1 = std::max(b.x1, p[0]), b.y1 = std::max(b.y1, p[1]);
    }
    boxes.push_back(b);
  }
  PolylineSet out;
  std::vector<std::array<double, 2>> wet, dry;
  for (int64_t line = 0; line < lines.line_count(); ++line) {
    bool open = false;  // a part is being written
    auto end_part = [&] {
      if (!open) return;
      open = false;
      const size_t first = size_t(out.offsets.back());
      bool distinct = false;  // fewer than two distinct points draw no ribbon
      for (size_t i = first + 1; i < out.points.size() && !distinct; ++i) distinct = out.points[i] != out.points[first];
      if (distinct) {
        out.end_line();
      } else {
        out.points.resize(first);
        out.radii.resize(first);
      }
    };
    const int64_t b0 = lines.line_begin(line), b1 = lines.line_end(line);
    for (int64_t v = b0; v + 1 < b1; ++v) {
      const Vec3 &a = lines.points[size_t(v)], &b = lines.points[size_t(v + 1)];
      // A ribbon turns at a point with its cross-section square to the mean
      // direction, its edges sweeping a disc there: near the water, a part
      // ends at the point (its end then square to its own last edge).
      if (open && disc_wet(rings, boxes, a[0], a[1], lines.radii[size_t(v)])) end_part();
      const double ra = lines.radii[size_t(v)], rb = lines.radii[size_t(v + 1)];
      const double r = std::max(ra, rb), ex = b[0] - a[0], ey = b[1] - a[1], len = std::hypot(ex, ey);
      wet.clear();
      if (len > 0) {
        const double ux = ex / len, uy = ey / len;
        // A cross-section square to a sloping edge leans along it: its top
        // lies flat x r sin(slope) ahead or behind (t units here).
        const double lean = flat * r * std::abs(b[2] - a[2]) / std::hypot(len, b[2] - a[2]) / len;
        const double bx0 = std::min(a[0], b[0]) - r, bx1 = std::max(a[0], b[0]) + r;
        const double by0 = std::min(a[1], b[1]) - r, by1 = std::max(a[1], b[1]) + r;
        for (const Ring& box : boxes) {
          if (box.x1 < bx0 || box.x0 > bx1 || box.y1 < by0 || box.y0 > by1) continue;
          for (int64_t i = box.begin, j = box.end - 1; i < box.end; j = i++) {
            const Vec3 &p = rings.points[size_t(j)], &q = rings.points[size_t(i)];
            if (std::max(p[0], q[0]) < bx0 || std::min(p[0], q[0]) > bx1 || std::max(p[1], q[1]) < by0 ||
                std::min(p[1], q[1]) > by1)
              continue;
            // The ring edge in the edge's frame: t in edge lengths, s in radii (a radius of 0: s in
            // world units, the band a line).
            const double k = r > 0 ? 1 / r : 1;
            const double t0 = ((p[0] - a[0]) * ux + (p[1] - a[1]) * uy) / len;
            const double t1 = ((q[0] - a[0]) * ux + (q[1] - a[1]) * uy) / len;
            const double s0 = (-(p[0] - a[0]) * uy + (p[1] - a[1]) * ux) * k;
            const double s1 = (-(q[0] - a[0]) * uy + (q[1] - a[1]) * ux) * k;
            // The part of it with |s| <= 1.
            double w0 = 0, w1 = 1;
            if (s0 == s1) {
              if (std::abs(s0) > 1) continue;
            } else {
              double c0 = (-1 - s0) / (s1 - s0), c1 = (1 - s0) / (s1 - s0);
              if (c0 > c1) std::swap(c0, c1);
              w0 = std::max(w0, c0), w1 = std::min(w1, c1);
              if (w0 > w1) continue;
            }
            const double ta = t0 + w0 * (t1 - t0), tb = t0 + w1 * (t1 - t0);
            const double lo = std::min(ta, tb), hi = std::max(ta, tb);
            if (hi >= -lean && lo <= 1 + lean) wet.push_back({std::max(0.0, lo - lean), std::min(1.0, hi + lean)});
          }
        }
      }
      // What is left, less the stretches whose centre is in the water.
      std::sort(wet.begin(), wet.end());
      dry.clear();
      double from = 0;
      for (const auto& w : wet) {
        if (w[0] > from) dry.push_back({from, w[0]});
        from = std::max(from, w[1]);
      }
      if (from < 1) dry.push_back({from, 1.0});
      auto at = [&](double t) {
        return Vec3{a[0] + t * ex, a[1] + t * ey, a[2] + t * (b[2] - a[2])};
      };
      auto radius_at = [&](double t) { return ra + t * (rb - ra); };
      bool reached_end = false;
      for (const auto& d : dry) {
        const double mid = 0.5 * (d[0] + d[1]);
        if (inside(rings, boxes, a[0] + mid * ex, a[1] + mid * ey)) continue;
        // A stretch from the edge's start continues the part the last edge ended.
        if (!(open && d[0] == 0)) {
          end_part();
          open = true;
          out.add(at(d[0]), radius_at(d[0]));
        }
        out.add(at(d[1]), radius_at(d[1]));
        reached_end = d[1] == 1;
      }
      if (!reached_end) end_part();
    }
    end_part();
  }
  return out;
}

}  // namespace ft::contour
