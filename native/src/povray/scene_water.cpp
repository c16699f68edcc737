// SPDX-License-Identifier: GPL-3.0-or-later
// Water in a scene: rivers as flattened ribbons in their beds and lakes as
// thin prisms cut to their shorelines, in ft_water.inc's material.
#include <algorithm>

#include "povray/scene_stages.hpp"
#include "povray/sdl_writer.hpp"
#include "povray/sphere_sweep_export.hpp"

namespace ft::pov::detail {
namespace {

// Flattened ribbons: the sweep is written FT_River_Flat times as high and
// squashed back, so its cross-section is a flat ellipse in the bed.
std::string rivers_sdl(const SceneContext& c) {
  const SceneParams& p = c.p;
  if (!p.rivers || p.rivers->vertex_count() == 0) return "";
  SceneLines l{p.rivers, LineKind::kGeneric};
  const double floor = automatic_line_radius(l, c.camera, c.extent, p.image_width);
  const double flat = 0.3;
  PolylineSet ribbon = *p.rivers;
  for (Vec3& q : ribbon.points) q[2] /= flat;
  // Another program's rivers keep the widths it shows; fracterra's are never
  // thinner than the floor, so they do not break into dots.
  for (double& r : ribbon.radii) r = p.scene_light ? (r > 0 ? r : floor) : std::max(r, floor);
  SweepOptions o = p.sweep;
  o.default_radius = floor;
  return "// rivers: " + std::to_string(p.rivers->line_count()) + " segments, radius half the width" +
         (p.scene_light ? std::string() : ", at least " + number(floor)) + "\n" + sweeps_sdl(ribbon, o, "  scale <1, " + number(flat) + ", 1>\n  material { FT_Water_Material }\n") +
         "\n";
}

std::string lake_sdl(const SceneLake& l, size_t k, double extent) {
  size_t n = 0;
  for (const auto& ring : l.rings) n += ring.size();
  if (n == 0) return "";
  std::string s = "// lake " + std::to_string(k) + "\n#declare FT_Lake_Points = array[" + std::to_string(n) + "] {";
  size_t i = 0;
  for (const auto& ring : l.rings)
    for (const Vec3& q : ring) {
      s += i % 4 == 0 ? "\n  " : " ";
      s += "<" + number(q[0]) + ", " + number(q[1]) + ">";
      if (++i < n) s += ",";
    }
  return s + "\n}\nFT_Lake(FT_Lake_Points, " + number(l.level) + ", " + number(0.002 * extent) + ")\n";
}

}  // namespace

std::string water_sdl(const SceneContext& c) {
  std::string s = rivers_sdl(c);
  for (size_t k = 0; k < c.p.lakes.size(); ++k) s += lake_sdl(c.p.lakes[k], k, c.extent);
  return s;
}

}  // namespace ft::pov::detail
