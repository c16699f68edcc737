// SPDX-License-Identifier: GPL-3.0-or-later
// A polygon mesh in the OpenSubdiv style (Far::TopologyDescriptor): shared
// vertices, a size per face and the faces' vertex indices one after another,
// plus optional sharp creases and corners. Plain data, no OpenSubdiv here, so
// io/ and capi/ can hold meshes without depending on subdiv/.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ft {

struct Mesh {
  std::vector<float> positions;     // xyz per vertex, 3 * vertex_count()
  std::vector<int32_t> face_sizes;  // vertices per face (>= 3)
  std::vector<int32_t> face_indices;  // sum(face_sizes) vertex indices, counter-clockwise
  // Edge creases: pairs of vertex indices (2 per crease) and a sharpness each,
  // 0 (smooth) .. 10 (infinitely sharp), as in OpenSubdiv and Blender.
  std::vector<int32_t> crease_pairs;
  std::vector<float> crease_sharpness;
  // Corner (vertex) sharpness, same range.
  std::vector<int32_t> corner_vertices;
  std::vector<float> corner_sharpness;

  size_t vertex_count() const { return positions.size() / 3; }
  size_t face_count() const { return face_sizes.size(); }
  std::array<float, 3> vertex(size_t i) const {
    return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
  }
};

// Newell's vector of the polygon idx[0..n): twice its vector area (normal
// times area, also for non-planar polygons), counter-clockwise = outward.
std::array<double, 3> face_vector_area(const Mesh& mesh, const int32_t* idx, int32_t n);

// Area-weighted vertex normals (unit length; zero for a vertex without faces
// of non-zero area), xyz per vertex. Serial and in face order: deterministic.
std::vector<float> mesh_vertex_normals(const Mesh& mesh);

}  // namespace ft
