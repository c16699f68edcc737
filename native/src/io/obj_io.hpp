// SPDX-License-Identifier: GPL-3.0-or-later
// Wavefront OBJ meshes. Reading screens the text (v, f and t lines checked
// and rewritten in canonical form, see obj_io.cpp), then goes through
// Debian's tinyobjloader: every shape of the file is merged into one mesh of
// shared vertices and polygons (up to 255 vertices per face, tinyobjloader's
// limit, refused beyond); normals, texture coordinates, materials, lines and
// points are ignored. Subdivision tags in
// OpenSubdiv's shape syntax are honoured, 0-based:
//   t crease 2/1/0 a b sharpness     (a chain: n/1/0 v0 .. v(n-1) sharpness)
//   t corner 1/1/0 v sharpness
// Writing emits v/f lines (and those tags) with 9 significant digits, so a
// float32 round trip is exact, through io/atomic_file.
#pragma once

#include <string>

#include "core/mesh.hpp"

namespace ft::io {

Mesh read_obj(const std::string& path);
Mesh decode_obj(const std::string& text, const std::string& name = "<memory>");
std::string encode_obj(const Mesh& mesh, const std::string& comment = "");
void write_obj(const Mesh& mesh, const std::string& path, const std::string& comment = "");

}  // namespace ft::io
