// SPDX-License-Identifier: GPL-3.0-or-later
#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "mesh/grid_mesh.hpp"

using ft::capi::guarded;

extern "C" {

FT_API ft_status ft_grid_counts_get(int32_t nx, int32_t ny, ft_grid_counts* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    *out = ft::mesh::grid_counts(nx, ny);
  });
}

FT_API ft_status ft_grid_vertices(const ft_heightfield* hf, double world_size_x, double world_size_y, double z_floor,
                                  float* xyz, size_t count) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::mesh::grid_vertices(hf->hf, world_size_x, world_size_y, z_floor, xyz, count);
  });
}

FT_API ft_status ft_grid_heights(const ft_heightfield* hf, double z_floor, float* z, size_t stride,
                                 size_t count) {
  return guarded([&] {
    ft::check_not_null("heightfield", hf);
    ft::mesh::grid_heights(hf->hf, z_floor, z, stride, count);
  });
}

FT_API ft_status ft_grid_topology(int32_t nx, int32_t ny, int32_t* loop_vertices, int32_t* loop_edges,
                                  size_t loop_capacity, int32_t* edge_vertices, size_t edge_capacity,
                                  int32_t* face_loop_starts, int32_t* face_loop_totals,
                                  size_t face_capacity) {
  return guarded([&] {
    ft::mesh::grid_topology(nx, ny, {loop_vertices, loop_edges, loop_capacity, edge_vertices, edge_capacity,
                               face_loop_starts, face_loop_totals, face_capacity});
  });
}

FT_API ft_status ft_grid_uvs(int32_t nx, int32_t ny, float* uv, size_t count) {
  return guarded([&] { ft::mesh::grid_uvs(nx, ny, uv, count); });
}

}  // extern "C"
