// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <memory>

#include "analysis/polyline_stats.hpp"
#include "capi/guard.hpp"
#include "polyline/polyline_params.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "polyline/polyline.hpp"

using ft::capi::guarded;

extern "C" {

FT_API ft_status ft_polyline_params_init(ft_polyline_params* p) {
  return guarded([&] {
    ft::check_not_null("params", p);
    *p = ft::polyline::default_polyline_params();
  });
}

FT_API ft_status ft_polyline_generate(const ft_polyline_params* p, ft_polylines** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    ft::check_not_null("params", p);
    auto h = std::make_unique<ft_polylines>();
    h->set = ft::polyline::generate_polylines(ft::upgraded(ft::polyline::polyline_param_table(), *p));
    *out = h.release();
  });
}

FT_API ft_status ft_polyline_measure(const ft_polylines* p, ft_polyline_stats* out) {
  return guarded([&] {
    ft::check_not_null("polylines", p);
    ft::check_not_null("out", out);
    const ft::analysis::PolylineMeasures m = ft::analysis::measure_polylines(p->set);
    ft_polyline_stats s{};
    s.line_count = p->set.line_count();
    s.vertex_count = p->set.vertex_count();
    s.eta = m.main.eta;
    s.chi = m.main.chi;
    s.gamma = m.main.gamma;
    s.length = m.total_length;
    s.mass_dimension = m.mass_dimension;
    s.box_dimension = m.box_ok ? m.box.dimension : NAN;
    s.box_dimension_std_error = m.box_ok ? m.box.std_error : NAN;
    s.box_min_size = m.box_ok ? m.box.min_size : NAN;
    s.box_max_size = m.box_ok ? m.box.max_size : NAN;
    s.box_sizes = m.box_ok ? int32_t(m.box.sizes.size()) : 0;
    ft::capi::write_result(out, s, sizeof(ft_polyline_stats), "ft_polyline_stats");
  });
}

}  // extern "C"
