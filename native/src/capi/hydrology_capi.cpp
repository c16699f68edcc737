// SPDX-License-Identifier: GPL-3.0-or-later
// The C ABI of the hydrology layer (fracterra/hydrology.h).
#include <algorithm>
#include <memory>
#include <string>

#include "capi/guard.hpp"
#include "capi/handles.hpp"
#include "contour/ribbon_clip.hpp"
#include "fracterra/fracterra.h"
#include "hydrology/hydrology.hpp"
#include "hydrology/hydrology_params.hpp"
#include "hydrology/network_measures.hpp"
#include "hydrology/river_files.hpp"

using ft::capi::guarded;

namespace {

void check_count(const char* what, int64_t given, int64_t want) {
  if (given != want)
    ft::invalid(std::string(what) + ": count must be " + std::to_string(want) + ", got " + std::to_string(given));
}

}  // namespace

extern "C" {

FT_API ft_status ft_hydrology_params_init(ft_hydrology_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::defaults_of<ft_hydrology_params>(ft::hydrology::hydrology_param_table());
  });
}

FT_API ft_status ft_rivers_extract(const ft_heightfield* terrain, const ft_hydrology_params* p,
                                   ft_river_network** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("terrain", terrain);
    ft::check_not_null("params", p);
    const ft::hydrology::HydrologyConfig c = ft::hydrology::from_c(*p);
    auto h = std::make_unique<ft_river_network>();
    h->net = ft::hydrology::extract_rivers(terrain->hf, c);
    *out = h.release();
  });
}

FT_API void ft_river_network_free(ft_river_network* net) { delete net; }

FT_API int32_t ft_river_network_segment_count(const ft_river_network* net) {
  return net ? int32_t(net->net.segments.size()) : 0;
}

FT_API int32_t ft_river_network_lake_count(const ft_river_network* net) {
  return net ? int32_t(net->net.water.lakes.size()) : 0;
}

FT_API ft_status ft_river_network_grid(const ft_river_network* net, int32_t* width, int32_t* height) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("width", width);
    ft::check_not_null("height", height);
    *width = net->net.grid.width;
    *height = net->net.grid.height;
  });
}

FT_API ft_status ft_river_network_polylines(const ft_river_network* net, ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("net", net);
    auto h = std::make_unique<ft_polylines>();
    h->set = net->net.lines;
    *out = h.release();
  });
}

FT_API ft_status ft_river_network_vertex_values(const ft_river_network* net, int32_t which, double* out,
                                                int64_t count) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("out", out);
    ft::check_int_range("which", which, 0, 3);
    const auto& n = net->net;
    const std::vector<double>* all[] = {&n.discharge, &n.width, &n.depth, &n.area};
    const auto& v = *all[which];
    check_count("ft_river_network_vertex_values", count, int64_t(v.size()));
    std::copy(v.begin(), v.end(), out);
  });
}

FT_API ft_status ft_river_network_segments(const ft_river_network* net, ft_river_segment* out, int32_t count) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("out", out);
    const auto& segs = net->net.segments;
    check_count("ft_river_network_segments", count, int64_t(segs.size()));
    for (size_t i = 0; i < segs.size(); ++i) {
      const auto& s = segs[i];
      out[i] = {s.first_vertex, s.vertex_count, s.order, s.downstream, int32_t(s.end), s.lake, s.from_lake,
                s.stream, s.length};
    }
  });
}

FT_API ft_status ft_river_network_lakes(const ft_river_network* net, ft_lake* out, int32_t count) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("out", out);
    const auto& n = net->net;
    const auto& lakes = n.water.lakes;
    check_count("ft_river_network_lakes", count, int64_t(lakes.size()));
    for (size_t i = 0; i < lakes.size(); ++i) {
      const auto& l = lakes[i];
      const double ox = l.outlet < 0 ? 0 : (l.outlet % n.grid.width) * n.grid.spacing;
      const double oy = l.outlet < 0 ? 0 : (l.outlet / n.grid.width) * n.grid.spacing;
      out[i] = {l.level, l.area, l.volume, ox, oy, l.outlet_segment, l.cells, l.first_ring, l.ring_count};
    }
  });
}

FT_API ft_status ft_river_network_min_depth(const ft_river_network* net, double* out) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("out", out);
    *out = net->net.water.min_depth;
  });
}

FT_API ft_status ft_river_network_lake_rings(const ft_river_network* net, ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("net", net);
    auto h = std::make_unique<ft_polylines>();
    h->set = net->net.lake_rings;
    *out = h.release();
  });
}

FT_API ft_status ft_river_network_ribbon_lines(const ft_river_network* net, ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("net", net);
    auto h = std::make_unique<ft_polylines>();
    h->set = ft::contour::clip_ribbons(net->net.lines, net->net.lake_rings, ft::hydrology::kRibbonFlat);
    *out = h.release();
  });
}

FT_API ft_status ft_river_network_water_mask(const ft_river_network* net, int32_t* out, int64_t count) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("out", out);
    const auto& label = net->net.water.label;
    check_count("ft_river_network_water_mask", count, int64_t(label.size()));
    std::copy(label.begin(), label.end(), out);
  });
}

FT_API ft_status ft_rivers_carve(const ft_heightfield* terrain, const ft_river_network* net, ft_heightfield** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("terrain", terrain);
    ft::check_not_null("net", net);
    auto h = std::make_unique<ft_heightfield>();
    h->hf = ft::hydrology::carve(terrain->hf, net->net);
    *out = h.release();
  });
}

FT_API ft_status ft_river_network_measures(const ft_river_network* net, ft_network_measures* out) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("out", out);
    const ft::hydrology::NetworkMeasures m = ft::hydrology::measure_network(net->net);
    ft_network_measures r{};
    r.horton_orders = m.has_horton ? m.horton.orders : 0;
    r.horton_fitted_orders = m.has_horton ? m.horton.fitted_orders : 0;
    r.hack_points = m.hack_points;
    r.bifurcation_ratio = m.horton.bifurcation, r.bifurcation_ratio_stderr = m.horton.bifurcation_stderr;
    r.length_ratio = m.horton.length, r.length_ratio_stderr = m.horton.length_stderr;
    r.total_length = m.total_length, r.land_area = m.land_area, r.drainage_density = m.drainage_density;
    r.hack_h = m.hack_h, r.hack_h_stderr = m.hack_h_stderr;
    r.segments = m.segments, r.lakes = m.lakes, r.vertices = m.vertices;
    for (int k = 0; k < 5; ++k) r.ends[k] = m.ends[k];
    for (size_t k = 0; k < m.horton.streams.size() && k < 32; ++k) r.streams[k] = m.horton.streams[k];
    for (size_t k = 0; k < m.horton.mean_length.size() && k < 32; ++k) r.mean_length[k] = m.horton.mean_length[k];
    ft::capi::write_result(out, r, sizeof(ft_network_measures), "ft_network_measures");
  });
}

FT_API ft_status ft_river_network_write(const ft_river_network* net, const ft_heightfield* terrain, const char* path,
                                        int32_t lakes_only) {
  return guarded([&] {
    ft::check_not_null("net", net);
    ft::check_not_null("path", path);
    const ft::GeoReference geo = terrain ? terrain->hf.georef() : ft::GeoReference();
    if (lakes_only) ft::hydrology::write_lakes(net->net, geo, path);
    else ft::hydrology::write_rivers(net->net, geo, path);
  });
}

}  // extern "C"
