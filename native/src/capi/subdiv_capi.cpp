// SPDX-License-Identifier: GPL-3.0-or-later
// C ABI of the subdiv capability: ft_mesh handles and ft_fractalize.
#include <cstring>
#include <memory>
#include <string>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "subdiv/fractalize_params.hpp"
#include "core/memory.hpp"
#include "core/mesh.hpp"
#include "fracterra/fracterra.h"
#include "subdiv/fractalize.hpp"
#include "subdiv/mesh_validation.hpp"

using ft::capi::guarded;

namespace {
constexpr int64_t kMaxCount = INT32_MAX;
}

extern "C" {

FT_API ft_status ft_mesh_create(const float* positions, int64_t vertex_count, const int32_t* face_sizes,
                                int64_t face_count, const int32_t* face_indices, const int32_t* crease_pairs,
                                const float* crease_sharpness, int64_t crease_count, ft_mesh** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_int_range("vertex_count", vertex_count, 0, kMaxCount);
    ft::check_int_range("face_count", face_count, 1, kMaxCount);
    ft::check_int_range("crease_count", crease_count, 0, kMaxCount);
    if (vertex_count > 0) ft::check_not_null("positions", positions);
    ft::check_not_null("face_sizes", face_sizes);
    ft::check_not_null("face_indices", face_indices);
    if (crease_count > 0) {
      ft::check_not_null("crease_pairs", crease_pairs);
      ft::check_not_null("crease_sharpness", crease_sharpness);
    }
    // Sizes first: the index count is only known once they are checked.
    int64_t corners = 0;
    for (int64_t f = 0; f < face_count; ++f) {
      if (face_sizes[f] < 3)
        ft::invalid("face " + std::to_string(f) + " has " + std::to_string(face_sizes[f]) +
                    " vertices; a face needs at least 3");
      corners += face_sizes[f];
      if (corners > kMaxCount) ft::fail(FT_ERR_TOO_LARGE, "more than 2^31 - 1 face corners");
    }
    ft::check_allocation(ft::checked_bytes(uint64_t(vertex_count), 12) + ft::checked_bytes(uint64_t(corners), 4) +
                             ft::checked_bytes(uint64_t(face_count), 4),
                         "the mesh");
    auto h = std::make_unique<ft_mesh>();
    ft::Mesh& m = h->mesh;
    m.positions.assign(positions, positions + 3 * vertex_count);
    m.face_sizes.assign(face_sizes, face_sizes + face_count);
    m.face_indices.assign(face_indices, face_indices + corners);
    if (crease_count > 0) {
      m.crease_pairs.assign(crease_pairs, crease_pairs + 2 * crease_count);
      m.crease_sharpness.assign(crease_sharpness, crease_sharpness + crease_count);
    }
    ft::subdiv::validate_mesh(m);
    *out = h.release();
  });
}

FT_API ft_status ft_mesh_set_corners(ft_mesh* mesh, const int32_t* vertices, const float* sharpness, int64_t count) {
  return guarded([&] {
    ft::check_not_null("mesh", mesh);
    ft::check_int_range("count", count, 0, kMaxCount);
    if (count > 0) {
      ft::check_not_null("vertices", vertices);
      ft::check_not_null("sharpness", sharpness);
    }
    ft::Mesh m = mesh->mesh;  // validate a copy: a bad call leaves the mesh as it was
    m.corner_vertices.assign(vertices, vertices + count);
    m.corner_sharpness.assign(sharpness, sharpness + count);
    ft::subdiv::validate_mesh(m);
    mesh->mesh = std::move(m);
  });
}

FT_API int64_t ft_mesh_vertex_count(const ft_mesh* m) { return m ? int64_t(m->mesh.vertex_count()) : 0; }
FT_API const float* ft_mesh_positions(const ft_mesh* m) { return m ? m->mesh.positions.data() : nullptr; }
FT_API int64_t ft_mesh_face_count(const ft_mesh* m) { return m ? int64_t(m->mesh.face_count()) : 0; }
FT_API const int32_t* ft_mesh_face_sizes(const ft_mesh* m) { return m ? m->mesh.face_sizes.data() : nullptr; }
FT_API int64_t ft_mesh_face_index_count(const ft_mesh* m) { return m ? int64_t(m->mesh.face_indices.size()) : 0; }
FT_API const int32_t* ft_mesh_face_indices(const ft_mesh* m) { return m ? m->mesh.face_indices.data() : nullptr; }
FT_API void ft_mesh_free(ft_mesh* m) { delete m; }

FT_API ft_status ft_fractalize_params_init(ft_fractalize_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::subdiv::default_fractalize_params();
  });
}

FT_API ft_status ft_fractalize(const ft_mesh* mesh, const ft_fractalize_params* p, ft_mesh** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("mesh", mesh);
    ft::check_not_null("params", p);
    auto h = std::make_unique<ft_mesh>();
    h->mesh = ft::subdiv::fractalize(mesh->mesh, ft::upgraded(ft::subdiv::fractalize_param_table(), *p));
    *out = h.release();
  });
}

}  // extern "C"
