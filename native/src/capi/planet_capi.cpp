// SPDX-License-Identifier: GPL-3.0-or-later
// The C ABI of the planet layer (fracterra/planet.h).
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "core/memory.hpp"
#include "fracterra/fracterra.h"
#include "planet/cube_sphere.hpp"
#include "planet/equirect.hpp"
#include "planet/icosphere.hpp"
#include "planet/sphere_spectrum.hpp"
#include "planet/planet_params.hpp"

using ft::capi::guarded;

namespace {

ft::planet::Planet make_planet(const ft_planet_params* p) {
  ft::check_not_null("params", p);
  return ft::planet::Planet(ft::planet::from_c(*p));
}

ft_heightfield* handle(ft::Heightfield hf) {
  auto h = std::make_unique<ft_heightfield>();
  h->hf = std::move(hf);
  return h.release();
}

void check_capacity(const char* what, size_t given, uint64_t want) {
  if (given < want)
    ft::invalid(std::string(what) + " holds " + std::to_string(given) + " elements, needs at least " +
                std::to_string(want));
}

// The caller's mesh arrays (each may be NULL) hold nv vertices and nf faces.
void check_mesh_capacity(int64_t nv, int64_t nf, int corners, const float* xyz, size_t xyz_count,
                         const int32_t* indices, size_t index_count, const char* index_name, const float* heights,
                         size_t height_count) {
  if (xyz) check_capacity("xyz", xyz_count, 3 * uint64_t(nv));
  if (indices) check_capacity(index_name, index_count, uint64_t(corners) * uint64_t(nf));
  if (heights) check_capacity("heights", height_count, uint64_t(nv));
}

// A mesh into the caller's arrays (each may be NULL), capacities checked first.
template <class MakeMesh>
void mesh_out(int64_t nv, int64_t nf, int corners, float* xyz, size_t xyz_count, int32_t* indices,
              size_t index_count, const char* index_name, float* heights, size_t height_count, MakeMesh&& make) {
  check_mesh_capacity(nv, nf, corners, xyz, xyz_count, indices, index_count, index_name, heights, height_count);
  std::vector<float> h;
  const ft::Mesh mesh = make(&h);
  if (xyz) std::copy(mesh.positions.begin(), mesh.positions.end(), xyz);
  if (indices) std::copy(mesh.face_indices.begin(), mesh.face_indices.end(), indices);
  if (heights) std::copy(h.begin(), h.end(), heights);
}

}  // namespace

extern "C" {

FT_API ft_status ft_planet_params_init(ft_planet_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_planet_params>(ft::planet::planet_param_table());
  });
}

FT_API ft_status ft_planet_face(const ft_planet_params* p, int32_t level, int32_t face, int64_t x0, int64_t y0,
                                int32_t width, int32_t height, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::planet::validate_patch(level, face, x0, y0, width, height);
    const ft::planet::Planet planet = make_planet(p);
    *out = handle(ft::planet::face_patch(planet, level, face, x0, y0, width, height));
  });
}

FT_API ft_status ft_planet_equirect(const ft_planet_params* p, int32_t width, int32_t height,
                                    ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_int_range("width", width, 2, 65536);
    ft::check_int_range("height", height, 2, 65536);
    const ft::planet::Planet planet = make_planet(p);
    *out = handle(ft::planet::equirect(planet, width, height));
  });
}

FT_API ft_status ft_planet_heights(const ft_planet_params* p, const double* xyz, int64_t count, float* heights) {
  return guarded([&] {
    ft::check_int_range("count", count, 0, int64_t(1) << 40);
    if (count == 0) return;
    ft::check_not_null("xyz", xyz);
    ft::check_not_null("heights", heights);
    const ft::planet::Planet planet = make_planet(p);
    ft::check_allocation(ft::checked_bytes(uint64_t(count), 24), "the points");
    ft::planet::Directions d{size_t(count)};
    for (int64_t i = 0; i < count; ++i) {
      const double a = xyz[3 * i], b = xyz[3 * i + 1], c = xyz[3 * i + 2];
      const double len = std::sqrt(a * a + b * b + c * c);
      if (!(len > 0) || !std::isfinite(len))
        ft::invalid("point " + std::to_string(i) + " has no direction (zero, infinite or NaN)");
      d.set(size_t(i), {a / len, b / len, c / len});
    }
    planet.heights(d, heights);
  });
}

FT_API ft_status ft_planet_sea_height(const ft_planet_params* p, double* out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    *out = make_planet(p).sea_height();
  });
}

FT_API ft_status ft_planet_mesh_counts(int32_t level, int64_t* vertices, int64_t* faces) {
  return guarded([&] {
    ft::check_int_range("level", level, 0, ft::planet::kMaxMeshLevel);
    if (vertices) *vertices = ft::planet::mesh_vertex_count(level);
    if (faces) *faces = ft::planet::mesh_face_count(level);
  });
}

FT_API ft_status ft_planet_mesh(const ft_planet_params* p, int32_t level, double vertical_scale, float* xyz,
                                size_t xyz_count, int32_t* quads, size_t quad_count, float* heights,
                                size_t height_count) {
  return guarded([&] {
    ft::check_int_range("level", level, 0, ft::planet::kMaxMeshLevel);
    // Straight into the caller's arrays: no copy, and no pass that reports no progress.
    check_mesh_capacity(ft::planet::mesh_vertex_count(level), ft::planet::mesh_face_count(level), 4, xyz, xyz_count,
                        quads, quad_count, "quads", heights, height_count);
    ft::planet::cube_sphere_arrays(make_planet(p), level, vertical_scale, {xyz, quads, heights});
  });
}

FT_API ft_status ft_planet_icosphere_counts(int32_t level, int64_t* vertices, int64_t* triangles) {
  return guarded([&] {
    ft::check_int_range("level", level, 0, ft::planet::kMaxIcosphereLevel);
    if (vertices) *vertices = ft::planet::icosphere_vertex_count(level);
    if (triangles) *triangles = ft::planet::icosphere_face_count(level);
  });
}

FT_API ft_status ft_planet_icosphere(const ft_planet_params* p, int32_t level, double vertical_scale, float* xyz,
                                     size_t xyz_count, int32_t* triangles, size_t triangle_count, float* heights,
                                     size_t height_count) {
  return guarded([&] {
    ft::check_int_range("level", level, 0, ft::planet::kMaxIcosphereLevel);
    mesh_out(ft::planet::icosphere_vertex_count(level), ft::planet::icosphere_face_count(level), 3, xyz,
             xyz_count, triangles, triangle_count, "triangles", heights, height_count,
             [&](std::vector<float>* h) {
               return ft::planet::icosphere_mesh(make_planet(p), level, vertical_scale, h);
             });
  });
}

FT_API ft_status ft_planet_power_spectrum(const ft_planet_params* p, int32_t lmax, double* power,
                                          size_t power_count) {
  return guarded([&] {
    ft::check_int_range("lmax", lmax, 2, ft::planet::kMaxSpectrumDegree);
    ft::check_not_null("power", power);
    check_capacity("power", power_count, uint64_t(lmax) + 1);
    const std::vector<double> c = ft::planet::angular_power_spectrum(make_planet(p), lmax);
    std::copy(c.begin(), c.end(), power);
  });
}

FT_API ft_status ft_planet_spectrum_hurst(const ft_planet_params* p, int32_t l_min, int32_t l_max, double* hurst,
                                          double* std_error) {
  return guarded([&] {
    ft::check_not_null("hurst", hurst);
    ft::check_int_range("l_max", l_max, 2, ft::planet::kMaxSpectrumDegree);
    ft::check_int_range("l_min", l_min, 1, l_max - 1);
    const ft::planet::SpectrumHurst r =
        ft::planet::spectrum_hurst(ft::planet::angular_power_spectrum(make_planet(p), l_max), l_min, l_max);
    *hurst = r.hurst;
    if (std_error) *std_error = r.std_error;
  });
}

}  // extern "C"
