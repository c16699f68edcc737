// SPDX-License-Identifier: GPL-3.0-or-later
// The C ABI of the splat layer (fracterra/splat.h).
#include <algorithm>
#include <cstring>
#include <memory>
#include <vector>
#include <string>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "splat/rules_json.hpp"
#include "splat/splat_map.hpp"
#include "splat/splat_params.hpp"

using ft::capi::guarded;

namespace {

ft::splat::SplatInputs inputs_of(const ft_heightfield* terrain, const ft_heightfield* deposited,
                                 const ft_heightfield* drainage_area) {
  ft::check_not_null("terrain", terrain);
  return {&terrain->hf, deposited ? &deposited->hf : nullptr, drainage_area ? &drainage_area->hf : nullptr};
}

void check_count(const char* what, size_t given, size_t want) {
  if (given < want)
    ft::invalid(std::string(what) + " holds " + std::to_string(given) + " values; it needs " + std::to_string(want));
}

// Copies `from` into the caller's `layers` (capacity, struct_size each) and
// sets *count: the built-in layers and a rules file's alike.
void copy_layers(const std::vector<ft_splat_params>& from, ft_splat_params* layers, int32_t capacity,
                 int32_t* count) {
  ft::check_not_null("count", count);
  *count = int32_t(from.size());
  if (!layers) return;
  if (capacity < int32_t(from.size()))
    ft::invalid("capacity must be at least " + std::to_string(from.size()) + ", got " + std::to_string(capacity));
  for (size_t k = 0; k < from.size(); ++k) {
    // The caller's struct_size decides how much is written (an older, smaller struct).
    const uint32_t size = layers[k].struct_size;
    if (size < offsetof(ft_splat_params, color) + sizeof(double[3]) || size > sizeof(ft_splat_params))
      ft::invalid("layers[" + std::to_string(k) + "].struct_size must be sizeof(ft_splat_params) = " +
                  std::to_string(sizeof(ft_splat_params)) + ", got " + std::to_string(size));
    ft_splat_params l = from[k];
    l.struct_size = size;
    std::memcpy(&layers[k], &l, size);
  }
}

}  // namespace

struct ft_splat_rules {
  ft::splat::SplatRules rules;
};

extern "C" {

FT_API ft_status ft_splat_params_init(ft_splat_params* layer) {
  return guarded([&] {
    ft::check_not_null("layer", layer);
    *layer = ft::defaults_of<ft_splat_params>(ft::splat::splat_param_table());
  });
}

FT_API ft_status ft_splat_default_layers(ft_splat_params* layers, int32_t capacity, int32_t* count) {
  return guarded([&] { copy_layers(ft::splat::default_layers(), layers, capacity, count); });
}

FT_API ft_status ft_splat_rules_read(const char* path, ft_splat_rules** out) {
  return guarded([&] {
    ft::check_not_null("out", out);
    *out = nullptr;
    ft::check_not_null("path", path);
    auto r = std::make_unique<ft_splat_rules>();
    r->rules = ft::splat::read_rules(path);
    *out = r.release();
  });
}

FT_API ft_status ft_splat_rules_layers(const ft_splat_rules* rules, ft_splat_params* layers, int32_t capacity,
                                       int32_t* count) {
  return guarded([&] {
    ft::check_not_null("rules", rules);
    copy_layers(rules->rules.layers, layers, capacity, count);
  });
}

FT_API void ft_splat_rules_free(ft_splat_rules* rules) { delete rules; }

FT_API ft_status ft_splat_weights(const ft_heightfield* terrain, const ft_heightfield* deposited,
                                  const ft_heightfield* drainage_area, const ft_splat_params* layers,
                                  int32_t layer_count, int32_t total, uint16_t* out, size_t out_count) {
  return guarded([&] {
    const auto in = inputs_of(terrain, deposited, drainage_area);
    ft::check_not_null("out", out);
    check_count("out", out_count, terrain->hf.size() * size_t(std::max(layer_count, 0)));
    const auto w = ft::splat::splat_weights(in, layers, layer_count, total);
    std::copy(w.begin(), w.end(), out);
  });
}

FT_API ft_status ft_splat_colors(const ft_heightfield* terrain, const ft_heightfield* deposited,
                                 const ft_heightfield* drainage_area, const ft_splat_params* layers,
                                 int32_t layer_count, float* rgb, size_t rgb_count) {
  return guarded([&] {
    const auto in = inputs_of(terrain, deposited, drainage_area);
    ft::check_not_null("rgb", rgb);
    check_count("rgb", rgb_count, terrain->hf.size() * 3);
    const auto c = ft::splat::splat_colors(in, layers, layer_count);
    std::copy(c.begin(), c.end(), rgb);
  });
}

FT_API ft_status ft_splat_colors_linear_rgba(const ft_heightfield* terrain, const ft_heightfield* deposited,
                                            const ft_heightfield* drainage_area, const ft_splat_params* layers,
                                            int32_t layer_count, int32_t threads, ft_progress_fn progress,
                                            void* progress_user, float* rgba, size_t rgba_count) {
  return guarded([&] {
    const auto in = inputs_of(terrain, deposited, drainage_area);
    ft::check_not_null("rgba", rgba);
    check_count("rgba", rgba_count, terrain->hf.size() * 4);
    ft::check_int_range("threads", threads, 0, 1024);
    ft::splat::splat_colors_linear_rgba(in, layers, layer_count, threads, ft::Progress(progress, progress_user),
                                        rgba);
  });
}

}  // extern "C"
