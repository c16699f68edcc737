// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <memory>

#include "analysis/polyline_stats.hpp"
#include "capi/guard.hpp"
#include "polyline/polyline_params.hpp"
#include "capi/handles.hpp"
#include "fracterra/fracterra.h"
#include "polyline/fpl_study.hpp"
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

FT_API ft_status ft_fpl_study(int32_t rng, const double* spreads, int32_t spread_count, const int32_t* depths,
                              int32_t depth_count, int32_t count, uint64_t seed, int32_t box_counting,
                              ft_progress_fn progress, void* progress_user, ft_fpl_study_row* out, int64_t out_count) {
  return guarded([&] {
    ft::check_not_null("spreads", spreads);
    ft::check_not_null("depths", depths);
    ft::check_not_null("out", out);
    ft::check_int_range("rng", rng, 0, 1);
    ft::check_int_range("spread_count", spread_count, 1, 1 << 20);
    ft::check_int_range("depth_count", depth_count, 1, 1 << 20);
    if (out_count != int64_t(spread_count) * depth_count)
      ft::invalid("ft_fpl_study: out_count must be spread_count x depth_count = " +
                  std::to_string(int64_t(spread_count) * depth_count) + ", got " + std::to_string(out_count));
    ft::polyline::FplStudyConfig c;
    c.rng = ft::polyline::FplRng(rng);
    c.spreads.assign(spreads, spreads + spread_count);
    c.depths.assign(depths, depths + depth_count);
    c.count = count;
    c.seed = seed;
    c.box_counting = box_counting != 0;
    c.progress = ft::Progress(progress, progress_user);
    const std::vector<ft::polyline::FplStudyRow> rows = ft::polyline::run_fpl_study(c);
    for (size_t i = 0; i < rows.size(); ++i) {
      const ft::polyline::FplStudyRow& r = rows[i];
      out[i] = ft_fpl_study_row{r.spread, r.depth, r.count, r.eta.mean, r.eta.se, r.chi.mean, r.chi.se,
                                r.gamma.mean, r.gamma.se, r.mass_dimension.mean, r.mass_dimension.se,
                                r.box_dimension.mean, r.box_dimension.se, r.paper_eta, r.paper_chi,
                                r.paper_gamma, r.paper_dimension};
    }
  });
}

}  // extern "C"
