// SPDX-License-Identifier: GPL-3.0-or-later
// Water in a scene: rivers as ribbons in their beds (river_ribbons.hpp), cut
// at the lakes' shorelines (contour/ribbon_clip.hpp), and lakes as thin
// prisms cut to their shorelines, in ft_water.inc's material.
#include <algorithm>

#include "contour/ribbon_clip.hpp"
#include "povray/scene_stages.hpp"
#include "povray/river_ribbons.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov::detail {
namespace {

// The river's cross-section: as high as this fraction of its width
// (Blender's RIVER_FLAT, ft_water.inc's FT_River_Flat, hydrology::kRibbonFlat), and the ring's
// vertices (the ellipse's widest and highest points among them).
constexpr double kRiverFlat = 0.3;
constexpr int kRibbonSides = 8;

std::string rivers_sdl(const SceneContext& c) {
  const SceneParams& p = c.p;
  if (!p.rivers || p.rivers->vertex_count() == 0) return "";
  SceneLines l{p.rivers, LineKind::kGeneric};
  const double floor = automatic_line_radius(l, c.camera, c.extent, p.image_width);
  // Another program's rivers keep the widths it shows (the floor only where
  // a point has none); fracterra's are never thinner than the floor, so they
  // do not break into dots.
  PolylineSet rivers = *p.rivers;
  if (!p.scene_light)
    for (double& r : rivers.radii) r = std::max(r, floor);
  // A ribbon over a lake would stand its height over the lake's surface (a
  // dark patch where a wide river joins two lakes): the rivers end where
  // their ribbons reach a shoreline and start again past it.
  PolylineSet shores;
  for (const SceneLake& lake : p.lakes)
    for (const auto& ring : lake.rings) {
      for (const Vec3& q : ring) shores.add(q);
      shores.end_line();
    }
  // The ribbon's height is a height: scaled with the terrain's (at the demo's
  // vertical scale 0.12 a ribbon 0.3 x its width high stood 8 times as high
  // over its bed as in the terrain's own frame, a wall over the lakes).
  const double flat = kRiverFlat * p.vertical_scale;
  if (shores.line_count() > 0) rivers = contour::clip_ribbons(rivers, shores, flat);
  const Mesh ribbons = river_ribbons(rivers, flat, kRibbonSides, floor);
  if (ribbons.face_count() == 0) return "";
  return "// rivers: " + std::to_string(p.rivers->line_count()) + " segments, ribbons as wide as the rivers" +
         (p.scene_light ? std::string() : ", at least " + number(2 * floor)) + "\n" +
         mesh2_sdl(ribbons, true, "  material { FT_Water_Material }\n") + "\n";
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
