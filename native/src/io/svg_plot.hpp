// SPDX-License-Identifier: GPL-3.0-or-later
// Small SVG charts for reports (the study and analysis plots): one or more
// panels in a grid, each with axes, ticks, optional log scales, series drawn
// as lines and/or points, and a legend. Also draws polyline sets (x, y) for
// a quick look. Written atomically like every fracterra file.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "core/polyline_set.hpp"

namespace ft::io {

struct SvgSeries {
  std::string label;             // "" keeps it out of the legend
  std::vector<double> x, y;      // same length; non-finite pairs are skipped
  std::vector<double> y_error;   // optional +- error bars (same length or empty)
  std::string color = "";        // "" picks from the palette by index
  bool line = true;
  bool points = false;
  bool dashed = false;
  double width = 1.5;
};

struct SvgPanel {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  double x_min = NAN, x_max = NAN, y_min = NAN, y_max = NAN;  // NaN: from the data
  std::vector<SvgSeries> series;
};

struct SvgFigure {
  std::string title;
  int columns = 2;
  double panel_width = 420, panel_height = 300;
  std::vector<SvgPanel> panels;
};

std::string render_svg(const SvgFigure& figure);
void write_svg(const std::string& path, const SvgFigure& figure);

// The x, y projection of a polyline set, fitted into width x height pixels
// (y up), stroke widths from the radii when `use_radii` (else 1 px).
std::string render_polylines_svg(const PolylineSet& set, double width, double height, bool use_radii = false);

}  // namespace ft::io
