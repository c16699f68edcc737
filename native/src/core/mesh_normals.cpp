// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>

#include "core/mesh.hpp"

namespace ft {

std::array<double, 3> face_vector_area(const Mesh& mesh, const int32_t* idx, int32_t n) {
  double nx = 0, ny = 0, nz = 0;
  for (int32_t i = 0; i < n; ++i) {
    const float* a = mesh.positions.data() + 3 * size_t(idx[i]);
    const float* b = mesh.positions.data() + 3 * size_t(idx[i + 1 < n ? i + 1 : 0]);
    nx += (double(a[1]) - b[1]) * (double(a[2]) + b[2]);
    ny += (double(a[2]) - b[2]) * (double(a[0]) + b[0]);
    nz += (double(a[0]) - b[0]) * (double(a[1]) + b[1]);
  }
  return {nx, ny, nz};
}

std::vector<float> mesh_vertex_normals(const Mesh& mesh) {
  std::vector<double> acc(mesh.positions.size(), 0.0);
  size_t first = 0;
  for (int32_t n : mesh.face_sizes) {
    const auto [nx, ny, nz] = face_vector_area(mesh, mesh.face_indices.data() + first, n);  // area-weighted
    for (int32_t i = 0; i < n; ++i) {
      double* v = acc.data() + 3 * size_t(mesh.face_indices[first + i]);
      v[0] += nx, v[1] += ny, v[2] += nz;
    }
    first += size_t(n);
  }
  std::vector<float> out(acc.size(), 0.0f);
  for (size_t i = 0; i < acc.size(); i += 3) {
    const double len = std::sqrt(acc[i] * acc[i] + acc[i + 1] * acc[i + 1] + acc[i + 2] * acc[i + 2]);
    if (len > 0)
      for (int k = 0; k < 3; ++k) out[i + k] = float(acc[i + k] / len);
  }
  return out;
}

}  // namespace ft
