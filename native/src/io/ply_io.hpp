// SPDX-License-Identifier: GPL-3.0-or-later
// Stanford PLY meshes, written binary little-endian (float xyz per vertex,
// a uchar count and int32 indices per face), through io/atomic_file. Read by
// Blender, MeshLab, CloudCompare and POV-Ray converters alike.
#pragma once

#include <string>

#include "core/mesh.hpp"

namespace ft::io {

void write_ply(const Mesh& mesh, const std::string& path, const std::string& comment = "");

}  // namespace ft::io
