// SPDX-License-Identifier: GPL-3.0-or-later
// Framing: what the camera frames (the land above the sea on a lattice of the
// terrain, every polyline and mesh vertex), the content box and the camera.
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "povray/scene_stages.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov::detail {

void grow(Vec3& lo, Vec3& hi, const Vec3& p) {
  for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
}

const char* kind_name(LineKind k) {
  switch (k) {
    case LineKind::kLightning: return "lightning";
    case LineKind::kCoastline: return "coastline";
    default: return "line";
  }
}

SceneContext frame_scene(const SceneParams& p, const std::string& pov_path, SceneSummary& sum) {
  SceneContext c{p, pov_path, folder_of(pov_path)};
  for (const auto& l : p.lines) c.stormy = c.stormy || l.kind == LineKind::kLightning;
  c.water = p.has_sea ? p.sea_level : NAN;
  Vec3 lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

  // The land above the sea on a 65 x 65 lattice of the terrain (POV axes).
  std::vector<Vec3> frame;
  if (p.terrain) {
    sum.terrain = place_terrain(*p.terrain, p.world_size_x, p.world_size_y, p.vertical_scale);
    const Heightfield& hf = *p.terrain;
    std::vector<Vec3> under;
    for (int j = 0; j <= 64; ++j)
      for (int i = 0; i <= 64; ++i) {
        const int x = int(std::lround(i * (hf.width() - 1) / 64.0)), y = int(std::lround(j * (hf.height() - 1) / 64.0));
        const Vec3 q{x * p.world_size_x / (hf.width() - 1), hf.at(x, y) * p.vertical_scale, y * p.world_size_y / (hf.height() - 1)};
        (p.has_sea && q[1] < c.water ? under : frame).push_back(q);
      }
    if (frame.empty())
      for (Vec3 q : under) frame.push_back({q[0], c.water, q[2]});  // all under the sea
  }
  for (const auto& l : p.lines)
    for (const Vec3& w : l.set->points) {
      Vec3 q = to_pov(w);
      if (l.kind == LineKind::kCoastline && p.has_sea) q[1] = c.water;
      frame.push_back(q);
    }
  for (const SceneMesh& m : p.meshes)
    for (size_t v = 0; v < m.mesh->vertex_count(); ++v) {
      const auto q = m.mesh->vertex(v);
      frame.push_back(to_pov({q[0], q[1], q[2]}));
    }
  if (frame.empty()) invalid("the scene is empty: its polyline sets and meshes hold no vertices");
  for (const Vec3& q : frame) grow(lo, hi, q);
  c.lo = sum.lo = lo;
  c.hi = sum.hi = hi;
  c.extent = std::max({hi[0] - lo[0], hi[2] - lo[2], hi[1] - lo[1], 1e-9});
  CameraOptions camera = p.camera;
  if (camera.elevation_deg == 0) camera.elevation_deg = auto_camera_elevation(p);
  c.camera = sum.camera = p.camera_given ? camera_from_pose(p.camera_pose) : frame_points(frame, camera);
  // The lights aim at the framed camera's target, or the content's middle.
  c.centre = p.camera_given ? Vec3{(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2}
                            : c.camera.look_at;
  return c;
}

}  // namespace ft::pov::detail
