// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/mesh2_export.hpp"

#include <cctype>
#include <cstdio>

#include "io/atomic_file.hpp"

namespace ft::pov {

std::string identifier(const std::string& name) {
  std::string id;
  bool upper = false;
  for (unsigned char c : name) {
    const bool ok = std::isalnum(c) || c == '_';
    id += ok && c < 128 ? char(c) : '_';
    upper = upper || std::isupper(c);
  }
  if (id.empty() || std::isdigit(static_cast<unsigned char>(id[0]))) id = "_" + id;
  if (!upper) id = "FT_" + id;
  return id;
}

std::string encode_mesh2(const Mesh& m, const std::string& name) {
  const std::string id = identifier(name);
  const std::vector<float> normals = mesh_vertex_normals(m);
  size_t triangles = 0;
  for (int32_t n : m.face_sizes) triangles += size_t(n - 2);
  std::string out;
  out.reserve(m.positions.size() * 28 + triangles * 24 + 256);
  char buf[128];
  std::snprintf(buf, sizeof buf, "// written by fracterra: %zu vertices, %zu triangles\n", m.vertex_count(), triangles);
  out += buf;
  out += "#declare " + id + " = mesh2 {\n";
  auto vectors = [&](const char* block, const std::vector<float>& xyz) {
    std::snprintf(buf, sizeof buf, "  %s {\n    %zu", block, xyz.size() / 3);
    out += buf;
    for (size_t i = 0; i < xyz.size(); i += 3) {
      std::snprintf(buf, sizeof buf, ",\n    <%.7g, %.7g, %.7g>", xyz[i], xyz[i + 1], xyz[i + 2]);
      out += buf;
    }
    out += "\n  }\n";
  };
  vectors("vertex_vectors", m.positions);
  vectors("normal_vectors", normals);  // one per vertex: mesh2 reuses face_indices for them
  std::snprintf(buf, sizeof buf, "  face_indices {\n    %zu", triangles);
  out += buf;
  size_t first = 0;
  for (int32_t n : m.face_sizes) {
    const int32_t* f = m.face_indices.data() + first;
    for (int32_t i = 1; i + 1 < n; ++i) {
      std::snprintf(buf, sizeof buf, ",\n    <%d, %d, %d>", f[0], f[i], f[i + 1]);
      out += buf;
    }
    first += size_t(n);
  }
  out += "\n  }\n}\n";
  return out;
}

void write_mesh2(const Mesh& mesh, const std::string& path, const std::string& name) {
  io::write_file_atomically(path, encode_mesh2(mesh, name));
}

}  // namespace ft::pov
