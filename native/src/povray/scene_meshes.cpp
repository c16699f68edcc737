// SPDX-License-Identifier: GPL-3.0-or-later
// Meshes in a scene (water surfaces, another program's objects): a mesh2 in
// POV axes, polygons split into triangle fans, with vertex normals when the
// mesh is smooth, in its material.
#include <cstdio>

#include "povray/scene_materials.hpp"
#include "povray/scene_stages.hpp"
#include "povray/sdl_writer.hpp"

namespace ft::pov::detail {
namespace {

void vectors(std::string& out, const char* block, const std::vector<float>& xyz) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "  %s { %zu", block, xyz.size() / 3);
  out += buf;
  for (size_t i = 0; i < xyz.size(); i += 3) {
    // World (x, y, z) is POV <x, z, y>.
    std::snprintf(buf, sizeof buf, ",\n    <%.9g, %.9g, %.9g>", double(xyz[i]), double(xyz[i + 2]), double(xyz[i + 1]));
    out += buf;
  }
  out += "\n  }\n";
}

size_t triangle_count(const Mesh& m) {
  size_t triangles = 0;
  for (int32_t n : m.face_sizes) triangles += size_t(n - 2);
  return triangles;
}

}  // namespace

std::string mesh2_sdl(const Mesh& m, bool smooth, const std::string& modifiers) {
  const size_t triangles = triangle_count(m);
  std::string s = "mesh2 {\n";
  vectors(s, "vertex_vectors", m.positions);
  if (smooth) vectors(s, "normal_vectors", mesh_vertex_normals(m));  // one per vertex, as the faces index
  char buf[96];
  std::snprintf(buf, sizeof buf, "  face_indices { %zu", triangles);
  s += buf;
  size_t first = 0;
  for (int32_t n : m.face_sizes) {
    const int32_t* f = m.face_indices.data() + first;
    for (int32_t i = 1; i + 1 < n; ++i) {
      std::snprintf(buf, sizeof buf, ",\n    <%d, %d, %d>", f[0], f[i], f[i + 1]);
      s += buf;
    }
    first += size_t(n);
  }
  return s + "\n  }\n" + modifiers + "}\n";
}

namespace {

std::string mesh_sdl(const SceneMesh& sm, size_t k, bool ambient) {
  const Mesh& m = *sm.mesh;
  if (m.face_count() == 0) return "";
  return "// mesh " + std::to_string(k) + ": " + std::to_string(m.vertex_count()) + " vertices, " +
         std::to_string(triangle_count(m)) + " triangles\n" +
         mesh2_sdl(m, sm.smooth, "  " + material_sdl(sm.material, ambient) + "\n") + "\n";
}

}  // namespace

std::string meshes_sdl(const SceneContext& c) {
  std::string s;
  for (size_t k = 0; k < c.p.meshes.size(); ++k) s += mesh_sdl(c.p.meshes[k], k, c.p.scene_light);
  return s;
}

}  // namespace ft::pov::detail
