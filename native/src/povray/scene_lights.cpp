// SPDX-License-Identifier: GPL-3.0-or-later
// Lights and sky: fracterra's own (a sun, a dim fill from the sky side and a
// graded sky, darker under a storm), or another program's: its sky colour as
// background and ambient light, and its sun or its lights.
#include <cmath>
#include <numbers>

#include "povray/scene_materials.hpp"
#include "povray/scene_stages.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov::detail {

std::string lights_and_sky_sdl(const SceneContext& c) {
  const SceneParams& p = c.p;
  const Vec3& centre = c.centre;
  if (p.scene_light && !p.lights.empty()) {  // another program's lights, in its units
    std::string s;
    for (const SceneLight& l : p.lights) s += light_sdl(l, centre, c.extent);
    return s + "\nbackground { rgb " + vec(p.sky_color) + " }\n\n";
  }
  const double saz = p.sun_azimuth_deg * std::numbers::pi / 180, sel = p.sun_elevation_deg * std::numbers::pi / 180;
  const double far = c.extent * 100;
  const Vec3 sun{centre[0] + far * std::sin(saz) * std::cos(sel), centre[1] + far * std::sin(sel),
                 centre[2] + far * std::cos(saz) * std::cos(sel)};
  std::string s = "light_source {\n  " + vec(sun) + "\n  color rgb " +
                  (p.scene_light ? vec(p.sun_color)
                   : c.stormy    ? std::string("<0.55, 0.58, 0.70>")
                                 : std::string("<1.25, 1.2, 1.1>")) +
                  "\n  parallel point_at " + vec(centre) + "\n}\n";
  if (p.scene_light)  // the scene's own sky lights the shadows (ambient_light)
    return s + "\nbackground { rgb " + vec(p.sky_color) + " }\n\n";
  // A dim fill from the sky side so shadows are not black.
  s += "light_source { " + vec({centre[0] - (sun[0] - centre[0]), centre[1] + far, centre[2] - (sun[2] - centre[2])}) +
       " color rgb " + (c.stormy ? "<0.10, 0.11, 0.16>" : std::string("<0.18, 0.2, 0.26>")) + " parallel point_at " +
       vec(centre) + " shadowless }\n\n";
  if (c.stormy)
    return s + "sky_sphere { pigment { gradient y color_map { [0 rgb <0.30, 0.31, 0.38>] [0.25 rgb <0.12, 0.13, "
               "0.20>] [1 rgb <0.04, 0.05, 0.10>] } } }\n\n";
  return s + "sky_sphere { pigment { gradient y color_map { [0 rgb <0.80, 0.86, 0.95>] [0.2 rgb <0.45, 0.62, "
             "0.90>] [1 rgb <0.18, 0.34, 0.72>] } } }\n\n";
}

std::string sea_sdl(const SceneContext& c) {
  return c.p.has_sea ? "plane { y, " + number(c.water) + " texture { FT_Sea_Tex } }\n\n" : std::string();
}

}  // namespace ft::pov::detail
