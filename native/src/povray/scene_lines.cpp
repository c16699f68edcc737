// SPDX-License-Identifier: GPL-3.0-or-later
// The polyline sets of a scene as sweeps in their kind's material: lightning
// glowing with a light at its foot, coastlines on the sea, lines in orange.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "povray/scene_materials.hpp"
#include "povray/scene_stages.hpp"
#include "povray/sdl_writer.hpp"
#include "povray/sphere_sweep_export.hpp"

namespace ft::pov {
namespace {

double median(std::vector<double>& v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + std::ptrdiff_t(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// The file's vertex radii as taper only: `base` times each radius over the
// set's largest (0 = `base`).
PolylineSet tapered(const PolylineSet& set, double base) {
  PolylineSet out = set;
  double top = 0;
  for (double r : set.radii) top = std::max(top, r);
  for (double& r : out.radii) r = top > 0 && r > 0 ? base * (r / top) : base;
  return out;
}

}  // namespace

// A tube thinner than about a pixel breaks up into dots; one much thicker
// than the smallest detail the image resolves (a pixel) hides it: 16385
// points of an FPL at a radius of 1% of the line were a smooth beaded worm.
// So the radius is 0.75 pixel at the distance of the lines (a tube 1.5 px
// wide), or a tenth of the median segment where that is larger (coarse
// lines: Koch depth 3 reads as a tube, not a hairline), but never more than
// the kind's style cap, the fixed fractions of the scene used before.
double automatic_line_radius(const SceneLines& l, const Camera& cam, double extent, int32_t image_width) {
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  std::vector<double> seg;
  for (int64_t i = 0; i < l.set->line_count(); ++i)
    for (int64_t v = l.set->line_begin(i); v < l.set->line_end(i); ++v) {
      const Vec3& a = l.set->points[size_t(v)];
      detail::grow(lo, hi, to_pov(a));
      if (v + 1 < l.set->line_end(i)) {
        const Vec3& b = l.set->points[size_t(v + 1)];
        const double d = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
        if (d > 0) seg.push_back(d);
      }
    }
  const double cap = (l.kind == LineKind::kLightning   ? 0.0035
                      : l.kind == LineKind::kCoastline ? 0.0012
                                                       : 0.003) * extent;
  double pixel = 0;
  if (lo[0] <= hi[0]) {
    const Vec3 c{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2};
    const double d = std::hypot(c[0] - cam.location[0], c[1] - cam.location[1], c[2] - cam.location[2]);
    pixel = 2 * d * std::tan(cam.fov_deg * std::numbers::pi / 360) / image_width;
  }
  const double m = median(seg);
  return std::max(0.75 * pixel, std::isnan(m) ? cap : std::min(0.1 * m, cap));
}

namespace detail {
namespace {

std::string line_set_sdl(const SceneContext& c, size_t i) {
  const SceneParams& p = c.p;
  const SceneLines& l = p.lines[i];
  SweepOptions o = p.sweep;
  o.default_radius = l.radius > 0 ? l.radius : automatic_line_radius(l, c.camera, c.extent, p.image_width);
  o.radius_scale = l.radius_scale;
  PolylineSet sized;
  const PolylineSet& set = l.radii_in_world_units ? *l.set : (sized = tapered(*l.set, o.default_radius));
  if (l.kind == LineKind::kCoastline && p.has_sea) o.use_z_override = true, o.z_override = c.water;
  const char* tex = l.kind == LineKind::kLightning   ? "FT_Lightning_Tex"
                    : l.kind == LineKind::kCoastline ? "FT_Coast_Tex"
                                                     : "FT_Line_Tex";
  // Another program's material stands for the kind's look: no glow, no light.
  const bool styled = !l.material;
  const std::string mods =
      styled ? std::string("  texture { ") + tex + " }\n" + (l.kind == LineKind::kLightning ? "  no_shadow\n" : "")
             : "  " + material_sdl(*l.material, p.scene_light) + "\n";
  std::string s = "// polyline set " + std::to_string(i + 1) + ": " + kind_name(l.kind) + ", " +
                  std::to_string(l.set->line_count()) + " lines, " + std::to_string(l.set->vertex_count()) +
                  " vertices, radius " + number(o.default_radius * o.radius_scale) +
                  (l.radii_in_world_units ? " where a vertex has none" : " (the file's radii as taper)") + "\n";
  s += sweeps_sdl(set, o, mods);
  if (styled && l.kind == LineKind::kLightning) {
    // A faint wide tube around the bolt reads as its glow. A `merge` would
    // hide the faint overlap of the pieces' end spheres but renders 3x
    // slower; at 85% transmit the overlap is barely visible.
    SweepOptions g = o;
    g.radius_scale = 4 * o.radius_scale;
    s += sweeps_sdl(set, g, "  texture { FT_Lightning_Glow_Tex }\n  no_shadow\n");
  }
  if (styled && l.kind == LineKind::kLightning && !l.set->points.empty()) {
    // The bolt lights what is near its foot (its lowest vertex).
    Vec3 foot = to_pov(l.set->points[0]);
    for (const Vec3& w : l.set->points)
      if (w[2] < foot[1]) foot = to_pov(w);
    foot[1] += 0.02 * c.extent;
    s += "light_source { " + vec(foot) + " color rgb <0.9, 0.95, 1.3>*2 fade_distance " + number(0.08 * c.extent) +
         " fade_power 2 shadowless }\n";
  }
  return s + "\n";
}

}  // namespace

std::string line_sets_sdl(const SceneContext& c) {
  std::string s;
  for (size_t i = 0; i < c.p.lines.size(); ++i) s += line_set_sdl(c, i);
  return s;
}

}  // namespace detail
}  // namespace ft::pov
