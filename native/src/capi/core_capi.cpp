// SPDX-License-Identifier: GPL-3.0-or-later
#include <cstring>
#include <string>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "core/build_features.hpp"
#include "core/memory.hpp"
#include "fracterra/fracterra.h"

namespace ft::capi {
namespace {
thread_local std::string g_last_error;
}
void set_last_error(const std::string& message) { g_last_error = message; }
void clear_last_error() { g_last_error.clear(); }
}  // namespace ft::capi

using ft::capi::guarded;

extern "C" {

FT_API uint32_t ft_abi_version(void) { return FT_ABI_VERSION; }
FT_API const char* ft_version_string(void) { return FT_VERSION_STRING; }  // from CMake
FT_API const char* ft_last_error(void) { return ft::capi::g_last_error.c_str(); }
FT_API const char* ft_build_features(void) { return ft::build_features(); }
FT_API const char* ft_heightfield_formats(void) { return ft::heightfield_formats(); }

FT_API int32_t ft_has_feature(const char* feature) {
  if (!feature) return 0;
  const std::string want(feature), have = std::string(" ") + ft::build_features() + " ";
  return !want.empty() && want.find(' ') == std::string::npos && have.find(" " + want + " ") != std::string::npos;
}

FT_API const char* ft_status_name(ft_status status) {
  switch (status) {
    case FT_OK: return "FT_OK";
    case FT_ERR_INVALID_ARGUMENT: return "FT_ERR_INVALID_ARGUMENT";
    case FT_ERR_OUT_OF_MEMORY: return "FT_ERR_OUT_OF_MEMORY";
    case FT_ERR_TOO_LARGE: return "FT_ERR_TOO_LARGE";
    case FT_ERR_IO: return "FT_ERR_IO";
    case FT_ERR_FORMAT: return "FT_ERR_FORMAT";
    case FT_ERR_CANCELLED: return "FT_ERR_CANCELLED";
    case FT_ERR_UNSUPPORTED: return "FT_ERR_UNSUPPORTED";
    case FT_ERR_INTERNAL: return "FT_ERR_INTERNAL";
    default: return "FT_ERR_UNKNOWN";
  }
}

FT_API uint64_t ft_memory_cap(void) { return ft::memory_cap(); }
FT_API void ft_set_memory_cap(uint64_t bytes) { ft::set_memory_cap(bytes); }

FT_API ft_status ft_heightfield_create(int32_t width, int32_t height, const float* data, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::Heightfield(width, height);
    if (data) std::memcpy(h->hf.data(), data, h->hf.size() * sizeof(float));
    else std::memset(h->hf.data(), 0, h->hf.size() * sizeof(float));
    *out = h.release();
  });
}

FT_API int32_t ft_heightfield_width(const ft_heightfield* h) { return h ? h->hf.width() : 0; }
FT_API int32_t ft_heightfield_height(const ft_heightfield* h) { return h ? h->hf.height() : 0; }
FT_API const float* ft_heightfield_data(const ft_heightfield* h) { return h ? h->hf.data() : nullptr; }
FT_API float* ft_heightfield_data_mut(ft_heightfield* h) { return h ? h->hf.data() : nullptr; }

FT_API ft_status ft_heightfield_copy(const ft_heightfield* h, float* dst, size_t count) {
  return guarded([&] {
    ft::check_not_null("heightfield", h);
    ft::check_not_null("dst", dst);
    if (count < h->hf.size())
      ft::invalid("dst holds " + std::to_string(count) + " floats; the heightfield has " + std::to_string(h->hf.size()));
    std::memcpy(dst, h->hf.data(), h->hf.size() * sizeof(float));
  });
}

FT_API ft_status ft_heightfield_stats(const ft_heightfield* h, double* min, double* max, double* mean, double* std) {
  return guarded([&] {
    ft::check_not_null("heightfield", h);
    const ft::HeightStats s = h->hf.stats();
    if (min) *min = s.min;
    if (max) *max = s.max;
    if (mean) *mean = s.mean;
    if (std) *std = s.std;
  });
}

FT_API double ft_heightfield_world_size(const ft_heightfield* h) { return h ? h->hf.world_size() : 0.0; }

FT_API ft_status ft_heightfield_set_world_size(ft_heightfield* h, double world_size) {
  return guarded([&] {
    ft::check_not_null("heightfield", h);
    ft::check_positive("world_size", world_size);
    h->hf.set_world_size(world_size);
  });
}

FT_API void ft_heightfield_free(ft_heightfield* h) { delete h; }

FT_API ft_status ft_polylines_create(const double* xyz, const double* radii, int64_t vertex_count,
                                     const int64_t* offsets, int64_t line_count, ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_int_range("vertex_count", vertex_count, 0, int64_t(1) << 34);
    ft::check_int_range("line_count", line_count, 0, int64_t(1) << 34);
    if (vertex_count > 0) ft::check_not_null("xyz", xyz);
    if (!offsets && line_count != 1 && vertex_count > 0)
      ft::invalid("offsets may be NULL only with line_count 1");
    if (offsets) {
      if (offsets[0] != 0 || offsets[line_count] != vertex_count)
        ft::invalid("offsets must start at 0 and end at vertex_count");
      for (int64_t i = 0; i < line_count; ++i)
        if (offsets[i + 1] < offsets[i]) ft::invalid("offsets must not decrease");
    }
    ft::check_allocation(ft::checked_bytes(uint64_t(vertex_count), 32), "the polyline set");
    auto h = std::make_unique<ft_polylines>();
    auto& s = h->set;
    s.points.resize(size_t(vertex_count));
    s.radii.assign(size_t(vertex_count), 0.0);
    for (int64_t i = 0; i < vertex_count; ++i) {
      s.points[size_t(i)] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
      if (radii) s.radii[size_t(i)] = radii[i];
      ft::check_finite("a vertex coordinate", xyz[3 * i] + xyz[3 * i + 1] + xyz[3 * i + 2]);
    }
    if (offsets) s.offsets.assign(offsets, offsets + line_count + 1);
    else s.offsets = {0, vertex_count};
    *out = h.release();
  });
}

FT_API int64_t ft_polylines_line_count(const ft_polylines* p) { return p ? p->set.line_count() : 0; }
FT_API int64_t ft_polylines_vertex_count(const ft_polylines* p) { return p ? p->set.vertex_count() : 0; }
FT_API const double* ft_polylines_xyz(const ft_polylines* p) {
  return p && !p->set.points.empty() ? p->set.points.front().data() : nullptr;
}
FT_API const double* ft_polylines_radii(const ft_polylines* p) { return p ? p->set.radii.data() : nullptr; }
FT_API const int64_t* ft_polylines_offsets(const ft_polylines* p) { return p ? p->set.offsets.data() : nullptr; }
FT_API void ft_polylines_free(ft_polylines* p) { delete p; }

}  // extern "C"
