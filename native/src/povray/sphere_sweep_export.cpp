// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/sphere_sweep_export.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov {
namespace {

struct Vertex {
  Vec3 p;        // POV axes
  double r;
  std::string text;  // "<x, y, z>" as written: the identity POV-Ray sees
};

Vertex make_vertex(const Vec3& p, double r) { return {p, r, vec(p)}; }

void write_point(std::string& s, const Vertex& v) { s += "  " + v.text + ", " + number(v.r) + "\n"; }

}  // namespace

void validate_sweep_options(const SweepOptions& o) {
  if (o.spline != SweepSpline::kLinear && o.spline != SweepSpline::kCubic)
    invalid("sweep spline must be 0 (linear) or 1 (cubic), got " + std::to_string(int(o.spline)));
  check_int_range("segments_per_sweep", o.segments_per_sweep, 1, int64_t(1) << 30);
  check_positive("default_radius", o.default_radius);
  check_positive("radius_scale", o.radius_scale);
  check_positive("tolerance", o.tolerance);
  if (o.use_z_override) check_finite("z_override", o.z_override);
}

std::string sweeps_sdl(const PolylineSet& set, const SweepOptions& o, const std::string& modifiers,
                       SweepStats* stats) {
  validate_sweep_options(o);
  if (set.radii.size() != set.points.size()) invalid("polyline radii and points differ in number");
  SweepStats st;
  std::vector<std::string> pieces;
  std::vector<Vertex> line;
  for (int64_t i = 0; i < set.line_count(); ++i) {
    line.clear();
    for (int64_t v = set.line_begin(i); v < set.line_end(i); ++v) {
      Vec3 w = set.points[size_t(v)];
      const double r0 = set.radii[size_t(v)];
      if (!std::isfinite(r0) || r0 < 0)
        invalid("polyline radii must be finite and >= 0 (0 = default radius), got " + format_number(r0) +
                " at vertex " + std::to_string(v));
      if (o.use_z_override) w[2] = o.z_override;
      Vertex vx = make_vertex(to_pov(w), (r0 > 0 ? r0 : o.default_radius) * o.radius_scale);
      if (!line.empty() && line.back().text == vx.text) {
        ++st.duplicates_removed;
        continue;
      }
      line.push_back(std::move(vx));
    }
    if (line.empty()) continue;
    if (line.size() == 1) {
      pieces.push_back("sphere { " + line[0].text + ", " + number(line[0].r) + " }\n");
      ++st.spheres;
      continue;
    }
    const int64_t n = int64_t(line.size());
    auto at = [&](int64_t k) -> Vertex {  // mirrored beyond the ends
      if (k < 0) return make_vertex({2 * line[0].p[0] - line[1].p[0], 2 * line[0].p[1] - line[1].p[1],
                                     2 * line[0].p[2] - line[1].p[2]}, line[0].r);
      if (k >= n) {
        const Vertex &e = line[size_t(n - 1)], &f = line[size_t(n - 2)];
        return make_vertex({2 * e.p[0] - f.p[0], 2 * e.p[1] - f.p[1], 2 * e.p[2] - f.p[2]}, e.r);
      }
      return line[size_t(k)];
    };
    for (int64_t a = 0; a < n - 1; a += o.segments_per_sweep) {
      const int64_t b = std::min(n - 1, a + o.segments_per_sweep);
      std::string s;
      if (o.spline == SweepSpline::kLinear) {
        s = "sphere_sweep { linear_spline " + std::to_string(b - a + 1) + ",\n";
        for (int64_t k = a; k <= b; ++k) write_point(s, line[size_t(k)]);
      } else {
        s = "sphere_sweep { cubic_spline " + std::to_string(b - a + 3) + ",\n";
        for (int64_t k = a - 1; k <= b + 1; ++k) write_point(s, at(k));
        s += "  tolerance " + number(o.tolerance) + "\n";
      }
      s += "}\n";
      pieces.push_back(std::move(s));
      ++st.sweeps;
    }
  }
  if (stats) *stats = st;
  if (pieces.empty()) return "";
  // POV-Ray warns about a union of one object, so a single piece is an object.
  std::string out = pieces.size() == 1 ? "object {\n" : "union {\n";
  for (auto& p : pieces) out += p;
  return out + modifiers + "}\n";
}

}  // namespace ft::pov
