// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ply_io.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {

void write_ply(const Mesh& mesh, const std::string& path, const std::string& comment) {
  static_assert(std::endian::native == std::endian::little, "PLY is written little-endian");
  std::string header = "ply\nformat binary_little_endian 1.0\n";
  if (!comment.empty()) header += "comment " + comment + "\n";
  header += "element vertex " + std::to_string(mesh.vertex_count()) +
            "\nproperty float x\nproperty float y\nproperty float z\n"
            "element face " + std::to_string(mesh.face_count()) +
            "\nproperty list uchar int vertex_indices\nend_header\n";
  AtomicFile out(path);
  out.write(header);
  out.write(std::string_view(reinterpret_cast<const char*>(mesh.positions.data()), mesh.positions.size() * 4));
  std::string faces;
  size_t k = 0;
  for (const int32_t n : mesh.face_sizes) {
    if (n < 3 || n > 255) invalid("a PLY face has 3..255 vertices, got " + std::to_string(n));
    faces.push_back(char(uint8_t(n)));
    const size_t at = faces.size();
    faces.resize(at + 4 * size_t(n));
    std::memcpy(faces.data() + at, mesh.face_indices.data() + k, 4 * size_t(n));
    k += size_t(n);
    if (faces.size() > (1u << 22)) {
      out.write(faces);
      faces.clear();
    }
  }
  out.write(faces);
  out.commit();
}

}  // namespace ft::io
