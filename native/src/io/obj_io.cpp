// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/obj_io.hpp"

#define TINYOBJLOADER_IMPLEMENTATION  // the Debian package's single-header build
#include <tiny_obj_loader.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {
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

// tinyobjloader parses every OBJ statement, and some of its paths convert
// numbers without range checks: a `vw` weight of 1e300 went through
// `int(inf)` (undefined behaviour, found by the fuzzer), atoi overflows on
// long indices, and a face of more than 255 vertices wraps its unsigned char
// count. So the text is screened first and the library sees only what we
// use, in canonical form: `v x y z` (numbers checked finite and within float,
// rewritten with 9 digits so float values survive exactly), `f a b c ...`
// (vertex indices only, each a non-zero 32-bit integer, at most 255),
// `t crease|corner n/r/0 ints reals` (counts matching the numbers given).
// Everything else (normals, texture coordinates, weights, lines, groups,
// materials, unknown statements) is ignored, as it was. Parsing uses
// std::from_chars, which does not depend on the C locale (Blender sets it).
class ObjScreen {
 public:
  explicit ObjScreen(const std::string& name) : name_(name) {}

  std::string screen(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    size_t at = 0;
    while (at < text.size()) {
      size_t end = text.find('\n', at);
      if (end == std::string_view::npos) end = text.size();
      ++line_;
      tokens(text.substr(at, end - at));
      at = end + 1;
      if (tok_.empty()) continue;
      const std::string_view kw = tok_[0];
      if (kw == "v") vertex(out);
      else if (kw == "f") face(out);
      else if (kw == "t") tag(out);
    }
    return out;
  }

 private:
  [[noreturn]] void refuse(const std::string& why) const {
    fail(FT_ERR_FORMAT,
         "cannot read the OBJ mesh '" + name_ + "': line " + std::to_string(line_) + ": " + why);
  }

  // Space- or tab-separated tokens; a '#' starts a comment.
  void tokens(std::string_view line) {
    tok_.clear();
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
      if (i >= line.size() || line[i] == '#') break;
      size_t j = i;
      while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r' && line[j] != '#') ++j;
      tok_.push_back(line.substr(i, j - i));
      i = j;
    }
  }

  float real(std::string_view t) const {
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    double v = 0;
    const auto r = t.size() <= 64 ? std::from_chars(t.data(), t.data() + t.size(), v)
                                  : std::from_chars_result{t.data(), std::errc::invalid_argument};
    if (r.ec == std::errc::result_out_of_range) {
      // Underflow (a negative exponent; 64 characters cannot underflow
      // otherwise) is zero, as a float would hold it; overflow is refused.
      const size_t e = t.find_first_of("eE");
      if (e != std::string_view::npos && e + 1 < t.size() && t[e + 1] == '-') return t[0] == '-' ? -0.0f : 0.0f;
      refuse("'" + std::string(t) + "' is beyond the float range");
    }
    if (r.ec != std::errc() || r.ptr != t.data() + t.size() || !std::isfinite(v))
      refuse("'" + std::string(t.substr(0, 64)) + "' is not a finite number");
    if (std::fabs(v) > double(std::numeric_limits<float>::max()))
      refuse("'" + std::string(t) + "' is beyond the float range");
    return float(v);
  }

  int32_t integer(std::string_view t) const {
    if (!t.empty() && t[0] == '+') t.remove_prefix(1);
    int64_t v = 0;
    const auto r = t.size() <= 20 ? std::from_chars(t.data(), t.data() + t.size(), v)
                                  : std::from_chars_result{t.data(), std::errc::invalid_argument};
    if (r.ec != std::errc() || r.ptr != t.data() + t.size() || v < -int64_t(INT32_MAX) || v > INT32_MAX)
      refuse("'" + std::string(t.substr(0, 64)) + "' is not an integer in the 32-bit range");
    return int32_t(v);
  }

  static void put(std::string& out, float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " %.9g", double(v));
    out += buf;
  }

  void vertex(std::string& out) {
    if (tok_.size() < 4) refuse("a vertex needs x y z");
    out += 'v';
    for (size_t k = 1; k <= 3; ++k) put(out, real(tok_[k]));
    for (size_t k = 4; k < tok_.size(); ++k) real(tok_[k]);  // w or a colour: checked, not used
    out += '\n';
  }

  void face(std::string& out) {
    const size_t n = tok_.size() - 1;
    if (n > 255) refuse("a face of " + std::to_string(n) + " vertices; at most 255 are supported");
    out += 'f';
    for (size_t k = 1; k <= n; ++k) {
      const std::string_view t = tok_[k];
      const int32_t i = integer(t.substr(0, t.find('/')));  // v, v/vt, v//vn, v/vt/vn
      if (i == 0) refuse("vertex index 0 (OBJ counts from 1, or back from -1)");
      out += ' ' + std::to_string(i);
    }
    out += '\n';
  }

  // OpenSubdiv's tags "t name ints/reals/strings values...": crease and
  // corner are kept, others ignored.
  void tag(std::string& out) {
    if (tok_.size() < 3 || (tok_[1] != "crease" && tok_[1] != "corner")) return;
    const std::string_view counts = tok_[2];
    const size_t a = counts.find('/'), b = a == std::string_view::npos ? a : counts.find('/', a + 1);
    if (b == std::string_view::npos) refuse("a tag's counts must be ints/reals/strings, e.g. 2/1/0");
    const int32_t ni = integer(counts.substr(0, a)), nr = integer(counts.substr(a + 1, b - a - 1)),
                  ns = integer(counts.substr(b + 1));
    if (ni < 0 || nr < 0 || ns < 0 || size_t(ni) + size_t(nr) + size_t(ns) != tok_.size() - 3)
      refuse("the tag's counts " + std::string(counts) + " do not match the " + std::to_string(tok_.size() - 3) +
             " values that follow");
    out += "t " + std::string(tok_[1]) + ' ' + std::to_string(ni) + '/' + std::to_string(nr) + "/0";
    for (int32_t k = 0; k < ni; ++k) out += ' ' + std::to_string(integer(tok_[3 + size_t(k)]));
    for (int32_t k = 0; k < nr; ++k) put(out, real(tok_[3 + size_t(ni) + size_t(k)]));
    out += '\n';
  }

  std::string name_;
  int64_t line_ = 0;
  std::vector<std::string_view> tok_;
};

}  // namespace

// Through read_file, so a missing file is FT_ERR_IO with the reason; .mtl
// files are not needed (materials are ignored).
Mesh read_obj(const std::string& path) { return decode_obj(read_file(path), path); }

Mesh decode_obj(const std::string& text, const std::string& name) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader r;
  r.ParseFromString(ObjScreen(name).screen(text), "", config);
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

}  // namespace ft::io
