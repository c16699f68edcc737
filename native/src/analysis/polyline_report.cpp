// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/polyline_report.hpp"

#include <cmath>

#include "analysis/polyline_stats.hpp"

namespace ft::analysis {
namespace {
nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
}  // namespace

nlohmann::json polyline_report(const PolylineSet& set) {
  const PolylineMeasures m = measure_polylines(set);
  nlohmann::json box;
  if (m.box_ok) {
    box = {{"dimension", m.box.dimension}, {"std_error", m.box.std_error}, {"min_size", m.box.min_size},
           {"max_size", m.box.max_size},   {"sizes", m.box.sizes},         {"counts", m.box.counts}};
  } else {
    box = {{"error", m.box_error}};
  }
  return {{"lines", set.line_count()},
          {"vertices", set.vertex_count()},
          {"length", m.total_length},
          {"eta", num(m.main.eta)},
          {"chi", num(m.main.chi)},
          {"gamma", num(m.main.gamma)},
          {"mass_dimension", num(m.mass_dimension)},
          {"box_counting", box}};
}

}  // namespace ft::analysis
