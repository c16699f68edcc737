// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/grid_mesh.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace ft::mesh {
namespace {

// Blender and most hosts index with int32, so the grid must stay below 2^31
// loops (a 23170^2 grid); 65536 per side is the terrain limit anyway.
constexpr int64_t kMaxIndex = (int64_t(1) << 31) - 1;

void check_capacity(const char* name, size_t have, int64_t need) {
  if (have < size_t(need))
    invalid(std::string(name) + " holds " + std::to_string(have) + " elements; the grid needs " +
            std::to_string(need));
}

}  // namespace

ft_grid_counts grid_counts(int32_t nx, int32_t ny) {
  check_int_range("nx", nx, 2, 65536);
  check_int_range("ny", ny, 2, 65536);
  ft_grid_counts c;
  c.vertices = int64_t(nx) * ny;
  c.edges = int64_t(ny) * (nx - 1) + int64_t(ny - 1) * nx;
  c.faces = int64_t(nx - 1) * (ny - 1);
  c.loops = 4 * c.faces;
  if (c.loops > kMaxIndex || c.edges * 2 > kMaxIndex)
    invalid("a " + std::to_string(nx) + " x " + std::to_string(ny) +
            " grid has more than 2^31 - 1 loops or edge indices; use a smaller grid");
  return c;
}

void grid_vertices(const Heightfield& hf, double world_size_x, double world_size_y, double z_floor, float* xyz,
                   size_t count) {
  check_not_null("xyz", xyz);
  check_positive("world_size_x", world_size_x);
  check_positive("world_size_y", world_size_y);
  if (std::isnan(z_floor)) invalid("z_floor must be a number (-INFINITY for none), got NaN");
  const int32_t nx = hf.width(), ny = hf.height();
  const ft_grid_counts c = grid_counts(nx, ny);
  check_capacity("xyz", count, 3 * c.vertices);
  const float* h = hf.data();
  const float floor = z_floor < -3.0e38 ? -INFINITY : float(z_floor);
#pragma omp parallel for schedule(static)
  for (int32_t row = 0; row < ny; ++row) {
    const float y = float((double(row) / (ny - 1) - 0.5) * world_size_y);
    float* dst = xyz + size_t(row) * nx * 3;
    const float* src = h + size_t(row) * nx;
    for (int32_t col = 0; col < nx; ++col) {
      dst[3 * col] = float((double(col) / (nx - 1) - 0.5) * world_size_x);
      dst[3 * col + 1] = y;
      dst[3 * col + 2] = std::max(src[col], floor);
    }
  }
}

void grid_heights(const Heightfield& hf, double z_floor, float* z, size_t stride, size_t count) {
  check_not_null("z", z);
  if (stride < 1) invalid("stride must be >= 1, got 0");
  if (std::isnan(z_floor)) invalid("z_floor must be a number (-INFINITY for none), got NaN");
  const size_t n = hf.size();
  if (n == 0) invalid("the heightfield is empty");
  check_capacity("z", count, int64_t((n - 1) * stride + 1));
  const float* h = hf.data();
  const float floor = z_floor < -3.0e38 ? -INFINITY : float(z_floor);
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < int64_t(n); ++i) z[size_t(i) * stride] = std::max(h[i], floor);
}

void grid_topology(int32_t nx, int32_t ny, const GridTopologyBuffers& b) {
  const ft_grid_counts c = grid_counts(nx, ny);
  if (b.loop_vertices || b.loop_edges) check_capacity("the loop buffers", b.loop_capacity, c.loops);
  if (b.edge_vertices) check_capacity("edge_vertices", b.edge_capacity, 2 * c.edges);
  if (b.face_loop_starts || b.face_loop_totals) check_capacity("the face buffers", b.face_capacity, c.faces);
  const int32_t ex = ny * (nx - 1);  // edges along x come first
  const int32_t fx = nx - 1;
#pragma omp parallel for schedule(static)
  for (int32_t row = 0; row < ny; ++row) {
    const int32_t v0 = row * nx;
    if (b.edge_vertices) {
      int32_t* e = b.edge_vertices + 2 * size_t(row) * fx;
      for (int32_t col = 0; col < fx; ++col) e[2 * col] = v0 + col, e[2 * col + 1] = v0 + col + 1;
      if (row + 1 < ny) {
        int32_t* ey = b.edge_vertices + 2 * (size_t(ex) + size_t(row) * nx);
        for (int32_t col = 0; col < nx; ++col) ey[2 * col] = v0 + col, ey[2 * col + 1] = v0 + nx + col;
      }
    }
    if (row + 1 == ny) continue;
    const size_t f0 = size_t(row) * fx;
    for (int32_t col = 0; col < fx; ++col) {
      const size_t f = f0 + col, l = 4 * f;
      if (b.loop_vertices) {
        int32_t* lv = b.loop_vertices + l;
        lv[0] = v0 + col, lv[1] = v0 + col + 1, lv[2] = v0 + nx + col + 1, lv[3] = v0 + nx + col;
      }
      if (b.loop_edges) {
        int32_t* le = b.loop_edges + l;
        le[0] = row * fx + col;             // (col,row)-(col+1,row)
        le[1] = ex + row * nx + col + 1;    // (col+1,row)-(col+1,row+1)
        le[2] = (row + 1) * fx + col;       // (col+1,row+1)-(col,row+1)
        le[3] = ex + row * nx + col;        // (col,row+1)-(col,row)
      }
      if (b.face_loop_starts) b.face_loop_starts[f] = int32_t(l);
      if (b.face_loop_totals) b.face_loop_totals[f] = 4;
    }
  }
}

void grid_uvs(int32_t nx, int32_t ny, float* uv, size_t count) {
  check_not_null("uv", uv);
  const ft_grid_counts c = grid_counts(nx, ny);
  check_capacity("uv", count, 2 * c.loops);
  const int32_t fx = nx - 1;
#pragma omp parallel for schedule(static)
  for (int32_t row = 0; row < ny - 1; ++row) {
    const float v0 = float(double(row) / (ny - 1)), v1 = float(double(row + 1) / (ny - 1));
    for (int32_t col = 0; col < fx; ++col) {
      const float u0 = float(double(col) / fx), u1 = float(double(col + 1) / fx);
      float* t = uv + 8 * (size_t(row) * fx + col);
      t[0] = u0, t[1] = v0, t[2] = u1, t[3] = v0, t[4] = u1, t[5] = v1, t[6] = u0, t[7] = v1;
    }
  }
}

}  // namespace ft::mesh
