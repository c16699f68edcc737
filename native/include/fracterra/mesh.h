// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/mesh.h
/// Regular grid meshes for hosts that fill meshes from flat arrays (Blender's
/// `foreach_set`, glTF-style buffers): vertex positions from a heightfield and
/// the topology of a quad grid, written into caller-allocated buffers so a
/// 1025 x 1025 grid needs no per-element work in the host's language.
///
/// Grid layout: vertex (col, row) has index row * nx + col; row grows with y
/// and col with x, as in a heightfield. Quad (col, row) has index
/// row * (nx - 1) + col and its four loops (corners) run counter-clockwise
/// seen from +z: (col, row), (col+1, row), (col+1, row+1), (col, row+1).
/// Edges: first the ny * (nx - 1) edges along x, row by row, edge
/// row * (nx - 1) + col joining (col, row)-(col+1, row); then the
/// (ny - 1) * nx edges along y, edge ny * (nx - 1) + row * nx + col joining
/// (col, row)-(col, row+1).
#ifndef FRACTERRA_MESH_H
#define FRACTERRA_MESH_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Element counts of an nx x ny vertex grid.
typedef struct ft_grid_counts {
  int64_t vertices;  ///< nx * ny
  int64_t edges;     ///< ny * (nx - 1) + (ny - 1) * nx
  int64_t faces;     ///< (nx - 1) * (ny - 1) quads
  int64_t loops;     ///< 4 * faces
} ft_grid_counts;

/// Counts of a grid of nx x ny vertices; nx, ny in 2..65536. `out` must not be NULL.
FT_API ft_status ft_grid_counts_get(int32_t nx, int32_t ny, ft_grid_counts* out);

/// Vertex positions of the heightfield as a grid spanning world_size_x x world_size_y
/// (world units, > 0) centred on the origin: x = (col / (nx - 1) - 0.5) * world_size_x,
/// y = (row / (ny - 1) - 0.5) * world_size_y, z = max(sample, z_floor) (pass -INFINITY
/// for no floor, e.g. a sea level otherwise). `xyz` holds `count` floats, at
/// least 3 * width * height; written as x, y, z triples in vertex order.
FT_API ft_status ft_grid_vertices(const ft_heightfield* hf, double world_size_x, double world_size_y,
                                  double z_floor, float* xyz, size_t count);

/// The same grid's z values only (one per vertex): z = max(sample, z_floor),
/// into `z`, which holds `count` floats (at least width * height). `stride`
/// (>= 1) is the distance between written floats: 3 with `z` pointing at the
/// first z of an xyz array rewrites heights in place (count then covers the
/// whole array from `z`: at least 3 * (width * height - 1) + 1).
FT_API ft_status ft_grid_heights(const ft_heightfield* hf, double z_floor, float* z, size_t stride,
                                 size_t count);

/// Topology of an nx x ny grid. Every buffer may be NULL (then skipped); a
/// non-NULL one must hold at least the number of int32 given:
///   loop_vertices, loop_edges: loops (vertex / edge index of each corner);
///   edge_vertices: 2 * edges (the two vertex indices of each edge);
///   face_loop_starts, face_loop_totals: faces (first loop of each quad, 4).
/// `capacity` arguments give each buffer's length in int32 elements.
FT_API ft_status ft_grid_topology(int32_t nx, int32_t ny,
                                  int32_t* loop_vertices, int32_t* loop_edges, size_t loop_capacity,
                                  int32_t* edge_vertices, size_t edge_capacity,
                                  int32_t* face_loop_starts, int32_t* face_loop_totals,
                                  size_t face_capacity);

/// Per-loop texture coordinates of the grid: u = col / (nx - 1),
/// v = row / (ny - 1), two floats per loop into `uv` (capacity `count`
/// floats, at least 2 * loops).
FT_API ft_status ft_grid_uvs(int32_t nx, int32_t ny, float* uv, size_t count);

#ifdef __cplusplus
}
#endif
#endif
