// SPDX-License-Identifier: GPL-3.0-or-later
// A mesh as a POV-Ray `mesh2` with per-vertex normals (smooth shading),
// declared under one identifier so a scene can `#include` the file and use
// `object { Name ... }`. Polygons are split into triangle fans (mesh2 holds
// triangles only). Coordinates are written as given; POV-Ray's left-handed
// axes mirror the mesh, which mesh2 does not mind (its triangles are
// two-sided and the normals mirror with it).
#pragma once

#include <string>

#include "core/mesh.hpp"

namespace ft::pov {

// A valid POV-Ray identifier from any name: characters other than letters,
// digits and '_' become '_', a leading digit gets a '_' in front, and a name
// without an upper-case letter gets the prefix "FT_" (every POV-Ray keyword
// is lower case, so the result can never be one).
std::string identifier(const std::string& name);

std::string encode_mesh2(const Mesh& mesh, const std::string& name);
void write_mesh2(const Mesh& mesh, const std::string& path, const std::string& name);

}  // namespace ft::pov
