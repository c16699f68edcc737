// SPDX-License-Identifier: GPL-3.0-or-later
// The terrain of a scene, in one of three kinds: a tile set's height_fields
// edge to edge, one terrain PNG (coloured by its colours PNG, or by altitude
// and slope), or, for fracterra's polylines alone, a ground to catch their
// shadows.
#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/platform.hpp"
#include "io/png_image.hpp"
#include "povray/scene_stages.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov::detail {
namespace {

std::string default_image_path(const std::string& pov_path) {
  std::filesystem::path p = platform::fs_path(pov_path);
  return platform::utf8_of(p.replace_extension(".terrain.png"));
}

// "x.pov" -> "x.colors.png", or beside a given terrain image: "t.png" -> "t.colors.png".
std::string colors_image_path(const std::string& pov_path, const std::string& image_path) {
  std::filesystem::path p = platform::fs_path(image_path.empty() ? pov_path : image_path);
  return platform::utf8_of(p.replace_extension(".colors.png"));
}

// The terrain colours as an 8-bit sRGB PNG (sRGB spends its 256 steps where
// the eye tells them apart; POV-Ray decodes it with `gamma srgb`).
void write_colors_png(const std::string& path, const Heightfield& hf, const float* rgb) {
  const size_t n = size_t(hf.width()) * size_t(hf.height()) * 3;
  std::vector<uint8_t> bytes(n);
  for (size_t i = 0; i < n; ++i) {
    const double c = std::clamp(double(rgb[i]), 0.0, 1.0);
    const double e = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
    bytes[i] = uint8_t(std::lround(255 * e));
  }
  io::write_png_rgb(path, hf.width(), hf.height(), bytes.data());
}

// The texture painting `place`'s terrain with the colours PNG `ref`: the
// image lies on x-y with row 0 on top; it is turned onto x-z with row 0 at
// z = 0 (as the height_field), projected down y, and stretched half a pixel
// past each edge so pixel centres land on the samples.
std::string colors_texture_sdl(const std::string& ref, const TerrainPlacement& place, bool scene_light) {
  const double w = place.width, h = place.height, sx = place.world_size_x, sy = place.world_size_y;
  return "  texture {\n    pigment {\n      image_map { png " + quoted(ref) + " gamma srgb interpolate 2 }\n" +
         "      scale <1, -1, 1> translate y rotate 90*x\n      scale " +
         vec({w / (w - 1) * sx, 1, h / (h - 1) * sy}) + "\n      translate " +
         vec({-0.5 * sx / (w - 1), 0, -0.5 * sy / (h - 1)}) + "\n    }\n" +
         // Under scene light the sky's ambient is the even light of a sky
         // dome, which a surface returns in full; else POV-Ray's default.
         (scene_light ? "    finish { ambient 1 diffuse 1 }\n" : "    finish { diffuse 1 }\n") + "  }\n";
}

std::string altitude_texture_sdl(const TerrainPlacement& t, double zw) {
  return "  FT_Terrain_Texture(" + number(t.z_min) + ", " + number(t.z_max) + ", " + number(zw) + ")\n";
}

// The tiles' own PNGs, one height_field each, in the set's common range.
std::string tiles_sdl(const SceneContext& c, SceneSummary& sum) {
  const SceneParams& p = c.p;
  sum.terrain.z_min = p.tiles->height_min * p.vertical_scale;
  sum.terrain.z_max = p.tiles->height_max * p.vertical_scale;
  const double zw = p.has_sea ? c.water : sum.terrain.z_min - 1;
  return "// " + std::to_string(p.tiles->tiles.size()) + " tiles edge to edge (fracterra tiles)\n" +
         "#declare FT_Terrain_Object = " + tiled_terrain_sdl(*p.tiles, p.vertical_scale, c.folder, c.water) +
         "object { FT_Terrain_Object\n" + altitude_texture_sdl(sum.terrain, zw) + "}\n\n";
}

std::string one_terrain_sdl(const SceneContext& c, SceneSummary& sum) {
  const SceneParams& p = c.p;
  const std::string image = p.image_path.empty() ? default_image_path(c.pov_path) : p.image_path;
  quoted(relative_path(image, c.folder));  // a path SDL cannot hold is refused before the PNG is written
  sum.terrain = write_heightfield_png(*p.terrain, image, p.world_size_x, p.world_size_y, p.vertical_scale);
  sum.image_path = image;
  const double zw = p.has_sea ? c.water : sum.terrain.z_min - 1;
  std::string s = "#declare FT_Terrain_Object = " + heightfield_sdl(relative_path(image, c.folder), sum.terrain, c.water);
  if (!p.terrain_colors) return s + "object { FT_Terrain_Object\n" + altitude_texture_sdl(sum.terrain, zw) + "}\n\n";
  const std::string colors = colors_image_path(c.pov_path, p.image_path);
  const std::string ref = relative_path(colors, c.folder);
  quoted(ref);
  write_colors_png(colors, *p.terrain, p.terrain_colors);
  sum.colors_path = colors;
  return s + "object { FT_Terrain_Object\n" + colors_texture_sdl(ref, sum.terrain, p.scene_light) + "}\n\n";
}

// Polylines alone: a ground to catch their shadows, just below them.
// Coastlines alone lie on a sea, where their white reads best.
std::string ground_sdl(const SceneContext& c) {
  bool coast = false;
  for (const auto& l : c.p.lines) coast = coast || l.kind == LineKind::kCoastline;
  return "plane { y, " + number(c.lo[1] - 0.02 * c.extent) + " texture { " + (coast ? "FT_Sea_Tex" : "FT_Ground_Tex") +
         " } }\n\n";
}

}  // namespace

std::string terrain_sdl(const SceneContext& c, SceneSummary& sum) {
  if (c.p.terrain && c.p.tiles) return tiles_sdl(c, sum);
  if (c.p.terrain) return one_terrain_sdl(c, sum);
  // Another program's scene has the ground it shows, or none.
  return c.p.scene_light ? std::string() : ground_sdl(c);
}

}  // namespace ft::pov::detail
