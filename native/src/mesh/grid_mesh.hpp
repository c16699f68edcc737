// SPDX-License-Identifier: GPL-3.0-or-later
// Flat-array descriptions of a regular quad grid (positions, topology, UVs)
// for hosts that fill meshes in bulk. The index layout is documented in
// fracterra/mesh.h; every function checks its buffer sizes first.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/heightfield.hpp"
#include "fracterra/mesh.h"

namespace ft::mesh {

ft_grid_counts grid_counts(int32_t nx, int32_t ny);

void grid_vertices(const Heightfield& hf, double world_size_x, double world_size_y, double z_floor, float* xyz,
                   size_t count);

void grid_heights(const Heightfield& hf, double z_floor, float* z, size_t stride, size_t count);

struct GridTopologyBuffers {
  int32_t* loop_vertices = nullptr;
  int32_t* loop_edges = nullptr;
  size_t loop_capacity = 0;
  int32_t* edge_vertices = nullptr;
  size_t edge_capacity = 0;
  int32_t* face_loop_starts = nullptr;
  int32_t* face_loop_totals = nullptr;
  size_t face_capacity = 0;
};

void grid_topology(int32_t nx, int32_t ny, const GridTopologyBuffers& out);

void grid_uvs(int32_t nx, int32_t ny, float* uv, size_t count);

}  // namespace ft::mesh
