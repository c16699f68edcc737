#include "io/obj_io.hpp"

#define TINYOBJLOADER_IMPLEMENTATION  // the Debian package's single-header build
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cstdio>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace ft {
namespace {

Mesh from_reader(const tinyobj::ObjReader& r, const std::string& name) {
  if (!r.Valid()) {
    std::string why = r.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    fail(FT_ERR_FORMAT, "cannot read the OBJ mesh '" + name + "': " + (why.empty() ? "parse error" : why));
  }
  Mesh m;
  const auto& v = r.GetAttrib().vertices;
  m.positions.assign(v.begin(), v.end());
  for (const auto& shape : r.GetShapes()) {
    const auto& sm = shape.mesh;
    for (unsigned char n : sm.num_face_vertices) m.face_sizes.push_back(n);
    for (const auto& idx : sm.indices) m.face_indices.push_back(idx.vertex_index);
    for (const auto& tag : sm.tags) {
      if (tag.name == "crease" && tag.intValues.size() >= 2 && !tag.floatValues.empty()) {
        for (size_t i = 0; i + 1 < tag.intValues.size(); ++i) {
          m.crease_pairs.push_back(tag.intValues[i]);
          m.crease_pairs.push_back(tag.intValues[i + 1]);
          m.crease_sharpness.push_back(tag.floatValues[0]);
        }
      } else if (tag.name == "corner") {
        for (size_t i = 0; i < tag.intValues.size(); ++i) {
          m.corner_vertices.push_back(tag.intValues[i]);
          m.corner_sharpness.push_back(tag.floatValues.empty() ? 10.0f
                                                               : tag.floatValues[std::min(i, tag.floatValues.size() - 1)]);
        }
      }
    }
  }
  if (m.face_sizes.empty()) fail(FT_ERR_FORMAT, "the OBJ file '" + name + "' has no faces ('f' lines)");
  return m;
}

}  // namespace

// Through read_file, so a missing file is FT_ERR_IO with the reason; .mtl
// files are not needed (materials are ignored).
Mesh read_obj(const std::string& path) { return decode_obj(read_file(path), path); }

Mesh decode_obj(const std::string& text, const std::string& name) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader r;
  r.ParseFromString(text, "", config);
  return from_reader(r, name);
}

std::string encode_obj(const Mesh& m, const std::string& comment) {
  std::string out = "# written by fracterra\n";
  if (!comment.empty()) {
    out += "# ";
    for (char c : comment) out += (c == '\n' || c == '\r') ? ' ' : c;  // one comment line
    out += "\n";
  }
  out.reserve(out.size() + m.positions.size() * 14 + m.face_indices.size() * 9);
  char buf[96];
  for (size_t i = 0; i < m.vertex_count(); ++i) {
    std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", m.positions[3 * i], m.positions[3 * i + 1],
                  m.positions[3 * i + 2]);
    out += buf;
  }
  size_t first = 0;
  for (int32_t n : m.face_sizes) {
    out += 'f';
    for (int32_t i = 0; i < n; ++i) {
      std::snprintf(buf, sizeof buf, " %d", m.face_indices[first + size_t(i)] + 1);  // OBJ is 1-based
      out += buf;
    }
    out += '\n';
    first += size_t(n);
  }
  for (size_t c = 0; c < m.crease_sharpness.size(); ++c) {
    std::snprintf(buf, sizeof buf, "t crease 2/1/0 %d %d %.9g\n", m.crease_pairs[2 * c], m.crease_pairs[2 * c + 1],
                  m.crease_sharpness[c]);
    out += buf;
  }
  for (size_t c = 0; c < m.corner_sharpness.size(); ++c) {
    std::snprintf(buf, sizeof buf, "t corner 1/1/0 %d %.9g\n", m.corner_vertices[c], m.corner_sharpness[c]);
    out += buf;
  }
  return out;
}

void write_obj(const Mesh& mesh, const std::string& path, const std::string& comment) {
  write_file_atomically(path, encode_obj(mesh, comment));
}

}  // namespace ft
