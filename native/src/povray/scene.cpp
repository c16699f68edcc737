// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/scene.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/atomic_file.hpp"
#include "povray/scene_materials.hpp"
#include "povray/scene_stages.hpp"
#include "povray/sdl_writer.hpp"
#include "splat/splat_map.hpp"

namespace ft::pov {

void validate_scene_params(const SceneParams& p) {
  if (p.terrain) validate_terrain(*p.terrain, p.world_size_x, p.world_size_y, p.vertical_scale);
  // sea_level, the sun and the camera are checked once, by
  // ft_pov_scene_params' table (pov_params.cpp), before they get here.
  for (const auto& l : p.lines) {
    check_not_null("polyline set", l.set);
    if (l.kind != LineKind::kGeneric && l.kind != LineKind::kLightning && l.kind != LineKind::kCoastline)
      invalid("polyline kind must be 0 (line), 1 (lightning) or 2 (coastline), got " +
              std::to_string(int(l.kind)));
    if (!(l.radius >= 0) || !std::isfinite(l.radius))
      invalid("polyline radius must be finite and >= 0 (0 = automatic), got " + format_number(l.radius));
    check_positive("polyline radius_scale", l.radius_scale);
  }
  check_int_range("image_width", p.image_width, 16, 16384);
  if (p.terrain_colors) {
    if (!p.terrain || p.tiles) invalid("terrain colours need a terrain of one piece (not tiles)");
    const size_t n = size_t(p.terrain->width()) * size_t(p.terrain->height()) * 3;
    for (size_t i = 0; i < n; ++i)
      if (!(p.terrain_colors[i] >= 0) || !std::isfinite(p.terrain_colors[i]))
        invalid("terrain colours must be finite and >= 0 (linear RGB, above 1 is clipped), got " +
                format_number(p.terrain_colors[i]) + " at value " + std::to_string(i));
  }
  for (int k = 0; k < 3; ++k) {
    check_range("sky_color", p.sky_color[size_t(k)], 0, 1000);
    check_range("sun_color", p.sun_color[size_t(k)], 0, 1000);
  }
  if (!p.terrain && p.lines.empty() && p.meshes.empty())
    invalid("a scene needs a terrain, a polyline set or a mesh");
  for (const SceneLight& l : p.lights) validate_light(l);
  for (const auto& l : p.lines)
    if (l.material) validate_material(*l.material, "line material");
  if (p.water_material) validate_material(*p.water_material, "water material");
  for (const SceneMesh& m : p.meshes) {
    check_not_null("scene mesh", m.mesh);
    validate_material(m.material, "mesh material");
    const size_t n = m.mesh->vertex_count();
    size_t corners = 0;
    for (int32_t k : m.mesh->face_sizes) {
      if (k < 3) invalid("a scene mesh's faces need 3 or more vertices, got " + std::to_string(k));
      corners += size_t(k);
    }
    if (corners != m.mesh->face_indices.size()) invalid("a scene mesh's face sizes do not add up to its indices");
    for (int32_t v : m.mesh->face_indices)
      if (v < 0 || size_t(v) >= n) invalid("a scene mesh's face names vertex " + std::to_string(v) + " of " + std::to_string(n));
    for (float x : m.mesh->positions) check_finite("scene mesh position", x);
  }
  for (const SceneLake& l : p.lakes) {
    check_finite("lake level", l.level);
    for (const auto& ring : l.rings)
      if (ring.size() < 4) invalid("a lake's shoreline ring needs at least 4 points (closed), got " + std::to_string(ring.size()));
  }
}

double auto_camera_elevation(const SceneParams& p) {
  if (p.terrain || p.tiles) return kTerrainElevationDeg;
  bool all_lightning = !p.lines.empty();
  for (const auto& l : p.lines) all_lightning = all_lightning && l.kind == LineKind::kLightning;
  return all_lightning ? kLightningElevationDeg : kLinesElevationDeg;
}

namespace detail {

bool has_water(const SceneParams& p) {
  bool meshes = false;
  for (const SceneMesh& m : p.meshes) meshes = meshes || m.material.water;
  return p.rivers || !p.lakes.empty() || p.water_material || meshes;
}

std::string header_sdl(const SceneContext& c) {
  const SceneParams& p = c.p;
  const std::string name = comment_text(platform::utf8_of(platform::fs_path(c.pov_path).filename()));
  std::string s;
  s += "// fracterra scene" + (p.title.empty() ? std::string() : ": " + comment_text(p.title)) + "\n";
  s += "// Render: fracterra render " + name + " --width 800 --height 600 --out image.png\n";
  s += "//     or: povray +W800 +H600 +A0.1 " + name + "\n";
  s += "// Axes: fracterra world (x, y, z up) is POV-Ray <x, z, y>; units are world units.\n";
  s += "#version 3.7;\n";
  s += "global_settings { assumed_gamma 1.0 max_trace_level 6" +
       (p.scene_light ? " ambient_light rgb " + vec(p.sky_color) : std::string()) + " }\n\n";
  s += "#ifndef(FT_Texture_Scale) #declare FT_Texture_Scale = " + number(c.extent / 200) + "; #end\n";
  s += "// ---- povray_macros/ft_terrain.inc, embedded so the scene stands alone ----\n";
  s += kFtTerrainInc;
  s += "// ---- end of ft_terrain.inc ----\n\n";
  s += std::string("#ifndef(FT_Stormy) #declare FT_Stormy = ") + (c.stormy ? "1" : "0") + "; #end\n";
  s += "// ---- povray_macros/ft_scene_materials.inc, embedded ----\n";
  s += kFtSceneMaterialsInc;
  s += "// ---- end of ft_scene_materials.inc ----\n";
  if (has_water(p)) {
    if (p.water_material)  // the scene's water instead of ft_water.inc's
      s += "#declare FT_Water_Tex = " + material_texture_sdl(*p.water_material, p.scene_light) +
           "\n#declare FT_Water_Interior = " + material_interior_sdl(*p.water_material) + "\n";
    s += "// ---- povray_macros/ft_water.inc, embedded ----\n";
    s += kFtWaterInc;
    s += "// ---- end of ft_water.inc ----\n";
  }
  s += "\n#declare FT_Scene_Min = " + vec(c.lo) + ";\n#declare FT_Scene_Max = " + vec(c.hi) + ";\n\n";
  return s;
}

}  // namespace detail

SceneSummary write_scene(const SceneParams& p, const std::string& pov_path) {
  validate_scene_params(p);
  io::AtomicFile out(pov_path);  // fails now, before the PNG, if the folder is unwritable
  SceneSummary sum;
  const detail::SceneContext c = detail::frame_scene(p, pov_path, sum);
  std::string s = detail::header_sdl(c);
  s += camera_sdl(c.camera);
  s += detail::lights_and_sky_sdl(c);
  s += detail::sea_sdl(c);
  s += detail::terrain_sdl(c, sum);
  s += detail::line_sets_sdl(c);
  s += detail::water_sdl(c);
  s += detail::meshes_sdl(c);
  out.write(s);
  out.commit();
  return sum;
}

void set_scene_terrain(SceneParams& p, const Heightfield& hf, double world_size_x, double vertical_scale,
                       double sea_fraction) {
  check_positive("terrain world_size_x", world_size_x);
  if (!(vertical_scale >= 0) || !std::isfinite(vertical_scale))
    invalid("vertical_scale must be finite and >= 0 (0 = automatic), got " + format_number(vertical_scale));
  if (!std::isnan(sea_fraction)) check_range("sea_fraction", sea_fraction, 0, 0.999);
  validate_terrain(hf, 1, 1, 1);
  const HeightStats st = hf.stats();
  if (!std::isfinite(st.min) || !std::isfinite(st.max)) invalid("the terrain holds NaN or infinite samples");
  p.terrain = &hf;
  p.world_size_x = world_size_x;
  p.world_size_y = world_size_x * double(hf.height() - 1) / double(hf.width() - 1);
  p.vertical_scale = vertical_scale > 0 ? vertical_scale
                     : st.max > st.min  ? 0.2 * world_size_x / (st.max - st.min)
                                        : 1.0;
  p.has_sea = !std::isnan(sea_fraction);
  if (p.has_sea) {
    std::vector<float> z(hf.data(), hf.data() + hf.size());
    const size_t k = std::min(z.size() - 1, size_t(sea_fraction * double(z.size())));
    std::nth_element(z.begin(), z.begin() + std::ptrdiff_t(k), z.end());
    // Exactly at a sample the sea would cut that sample's flat neighbourhood
    // in stripes: sit a hair above it.
    p.sea_level = (double(z[k]) + 1e-4 * (st.max - st.min)) * p.vertical_scale;
  }
}

SceneSummary write_terrain_scene(const Heightfield& hf, const std::string& pov_path) {
  SceneParams p;
  // A terrain that records its world size is placed in those units with its
  // heights unscaled (they share the unit, as in Blender); one that does not
  // is 1 wide with a relief of 20% of that.
  if (hf.world_size() > 0) set_scene_terrain(p, hf, hf.world_size(), 1.0);
  else set_scene_terrain(p, hf);
  p.title = "terrain " + std::to_string(hf.width()) + " x " + std::to_string(hf.height());
  // Coloured by the built-in splat rules, as `fracterra splat --color` and
  // the Blender material colour it.
  const auto layers = splat::default_layers();
  const std::vector<float> colors =
      splat::splat_colors_linear({&hf, nullptr, nullptr}, layers.data(), int32_t(layers.size()));
  p.terrain_colors = colors.data();
  return write_scene(p, pov_path);
}

SceneSummary write_polyline_scene(const SceneLines& lines, const std::string& pov_path, const CameraOptions& camera,
                                  int32_t image_width) {
  SceneParams p;
  p.lines.push_back(lines);
  p.camera = camera;
  p.image_width = image_width;
  p.title = std::string(detail::kind_name(lines.kind)) + " polylines";
  return write_scene(p, pov_path);
}

}  // namespace ft::pov
