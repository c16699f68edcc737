// SPDX-License-Identifier: GPL-3.0-or-later
// Plots to files: .svg as written by io/svg_plot, .png through rsvg-convert
// (Debian librsvg2-bin, a run-time package of `analyze --plot x.png`).
#pragma once

#include <string>

#include "io/svg_plot.hpp"

namespace ft::cli {

// Writes `fig` to `path` (.svg or .png) under a temporary name, renamed on
// success like every fracterra file. Throws ft::Error (FT_ERR_IO when
// rsvg-convert is missing or fails, with what to do instead).
void write_plot(const std::string& path, const io::SvgFigure& fig);

}  // namespace ft::cli
