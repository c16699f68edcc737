// SPDX-License-Identifier: GPL-3.0-or-later
// The stages of write_scene, in the order their SDL appears in a scene:
// framing (the content box and the camera), the header, lights and sky, the
// sea, the terrain (one PNG, tiles, or a ground for polylines alone), the
// polyline sweeps, then water (rivers, lakes) and meshes. Each stage reads
// the SceneContext framing made and returns its part of the scene.
#pragma once

#include <string>
#include <vector>

#include "povray/scene.hpp"

namespace ft::pov::detail {

struct SceneContext {
  const SceneParams& p;
  std::string pov_path, folder;  // the scene and its folder (images are relative to it)
  bool stormy = false;           // some line set is lightning: fracterra's storm light
  double water = 0;              // world z of the sea; NaN without one
  Vec3 lo{}, hi{};               // the framed content's box, POV axes
  double extent = 0;             // its largest side (> 0)
  Camera camera{};
  Vec3 centre{};                 // where the lights aim
};

void grow(Vec3& lo, Vec3& hi, const Vec3& p);
const char* kind_name(LineKind k);

// Frames the scene: fills sum's camera, box and terrain placement.
SceneContext frame_scene(const SceneParams& p, const std::string& pov_path, SceneSummary& sum);
// The title comments, #version, global_settings and the embedded includes.
std::string header_sdl(const SceneContext& c);
// fracterra's sun, fill and sky, or the scene's own light (scene_light).
std::string lights_and_sky_sdl(const SceneContext& c);
// The sea plane at p.sea_level (has_sea), "" without one.
std::string sea_sdl(const SceneContext& c);
// The terrain: its tiles, its PNG (written now, with its colours PNG), or a
// ground under polylines alone. Fills sum's image paths and height range.
std::string terrain_sdl(const SceneContext& c, SceneSummary& sum);
// Every polyline set as sweeps in its kind's material.
std::string line_sets_sdl(const SceneContext& c);
// Rivers as water ribbons in their beds (river_ribbons.hpp) and lakes as
// water prisms.
std::string water_sdl(const SceneContext& c);
// A mesh as a mesh2 in POV axes (polygons as triangle fans), with vertex
// normals when smooth; `modifiers` (SDL lines) go before its closing brace.
std::string mesh2_sdl(const Mesh& m, bool smooth, const std::string& modifiers);
// The meshes, each a mesh2 in its material.
std::string meshes_sdl(const SceneContext& c);
// Whether the scene holds water (and so embeds ft_water.inc).
bool has_water(const SceneParams& p);

}  // namespace ft::pov::detail
