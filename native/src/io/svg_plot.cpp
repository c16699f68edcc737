// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/svg_plot.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {
namespace {

const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string tick_label(double v) {
  char buf[32];
  if (v == 0) return "0";
  const double a = std::fabs(v);
  if (a >= 1e5 || a < 1e-3) std::snprintf(buf, sizeof buf, "%.0e", v);
  else std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    if (c == '<') o += "&lt;";
    else if (c == '>') o += "&gt;";
    else if (c == '&') o += "&amp;";
    else o += c;
  }
  return o;
}

// Maps data to pixels along one axis.
struct Axis {
  bool log = false;
  double lo = 0, hi = 1;     // data range
  double p0 = 0, p1 = 1;     // pixel range
  double t(double v) const { return log ? std::log10(v) : v; }
  double map(double v) const {
    const double a = t(lo), b = t(hi);
    return p0 + (t(v) - a) / (b - a) * (p1 - p0);
  }
  bool valid(double v) const { return std::isfinite(v) && (!log || v > 0); }
  // Round tick positions: 1-2-5 steps (linear) or decades (log).
  std::vector<double> ticks() const {
    std::vector<double> out;
    if (log) {
      const int a = int(std::floor(std::log10(lo) + 1e-9)), b = int(std::ceil(std::log10(hi) - 1e-9));
      const bool sparse = b - a > 1;
      for (int e = a; e <= b; ++e)
        for (double m : sparse ? std::vector<double>{1} : std::vector<double>{1, 2, 5}) {
          const double v = m * std::pow(10.0, e);
          if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) out.push_back(v);
        }
      return out;
    }
    const double span = hi - lo;
    const double raw = span / 5;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
    for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step)
      out.push_back(std::fabs(v) < step * 1e-9 ? 0.0 : v);
    return out;
  }
};

void data_range(const SvgPanel& p, bool x_axis, bool log, double& lo, double& hi) {
  lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const SvgSeries& s : p.series)
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      const double e = !x_axis && i < s.y_error.size() ? s.y_error[i] : 0.0;
      for (double v : x_axis ? std::vector<double>{s.x[i]} : std::vector<double>{s.y[i] - e, s.y[i] + e})
        if (std::isfinite(v) && (!log || v > 0)) lo = std::min(lo, v), hi = std::max(hi, v);
    }
  if (!std::isfinite(lo)) lo = log ? 1 : 0, hi = log ? 10 : 1;
  if (hi <= lo) {
    const double d = log ? 0 : (std::fabs(lo) > 0 ? 0.1 * std::fabs(lo) : 1);
    lo = log ? lo / 2 : lo - d, hi = log ? hi * 2 : hi + d;
  } else if (!log && !x_axis) {
    const double pad = 0.05 * (hi - lo);
    lo -= pad, hi += pad;
  }
}

void render_panel(std::string& o, const SvgPanel& p, double ox, double oy, double w, double h) {
  const double left = 62, right = 12, top = 28, bottom = 44;
  Axis ax, ay;
  ax.log = p.log_x, ay.log = p.log_y;
  data_range(p, true, ax.log, ax.lo, ax.hi);
  data_range(p, false, ay.log, ay.lo, ay.hi);
  if (std::isfinite(p.x_min)) ax.lo = p.x_min;
  if (std::isfinite(p.x_max)) ax.hi = p.x_max;
  if (std::isfinite(p.y_min)) ay.lo = p.y_min;
  if (std::isfinite(p.y_max)) ay.hi = p.y_max;
  ax.p0 = ox + left, ax.p1 = ox + w - right;
  ay.p0 = oy + h - bottom, ay.p1 = oy + top;
  o += "<g>\n<rect x='" + fmt(ax.p0) + "' y='" + fmt(ay.p1) + "' width='" + fmt(ax.p1 - ax.p0) + "' height='" +
       fmt(ay.p0 - ay.p1) + "' fill='none' stroke='#333'/>\n";
  o += "<text x='" + fmt(ox + w / 2) + "' y='" + fmt(oy + 18) + "' text-anchor='middle' font-size='13'>" +
       escape(p.title) + "</text>\n";
  for (double v : ax.ticks()) {
    const double x = ax.map(v);
    o += "<line x1='" + fmt(x) + "' y1='" + fmt(ay.p0) + "' x2='" + fmt(x) + "' y2='" + fmt(ay.p1) +
         "' stroke='#ddd'/><text x='" + fmt(x) + "' y='" + fmt(ay.p0 + 14) +
         "' text-anchor='middle' font-size='10'>" + tick_label(v) + "</text>\n";
  }
  for (double v : ay.ticks()) {
    const double y = ay.map(v);
    o += "<line x1='" + fmt(ax.p0) + "' y1='" + fmt(y) + "' x2='" + fmt(ax.p1) + "' y2='" + fmt(y) +
         "' stroke='#ddd'/><text x='" + fmt(ax.p0 - 4) + "' y='" + fmt(y + 3) +
         "' text-anchor='end' font-size='10'>" + tick_label(v) + "</text>\n";
  }
  o += "<text x='" + fmt((ax.p0 + ax.p1) / 2) + "' y='" + fmt(oy + h - 8) + "' text-anchor='middle' font-size='11'>" +
       escape(p.x_label) + "</text>\n";
  o += "<text transform='translate(" + fmt(ox + 14) + "," + fmt((ay.p0 + ay.p1) / 2) +
       ") rotate(-90)' text-anchor='middle' font-size='11'>" + escape(p.y_label) + "</text>\n";
  o += "<clipPath id='c" + fmt(ox) + "_" + fmt(oy) + "'><rect x='" + fmt(ax.p0) + "' y='" + fmt(ay.p1) +
       "' width='" + fmt(ax.p1 - ax.p0) + "' height='" + fmt(ay.p0 - ay.p1) + "'/></clipPath>\n";
  o += "<g clip-path='url(#c" + fmt(ox) + "_" + fmt(oy) + ")'>\n";
  int legend = 0;
  for (size_t k = 0; k < p.series.size(); ++k) {
    const SvgSeries& s = p.series[k];
    const std::string color = s.color.empty() ? kPalette[k % 8] : s.color;
    std::string path;
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!ax.valid(s.x[i]) || !ay.valid(s.y[i])) continue;
      path += (path.empty() ? "M" : " L") + fmt(ax.map(s.x[i])) + "," + fmt(ay.map(s.y[i]));
    }
    if (s.line && !path.empty())
      o += "<path d='" + path + "' fill='none' stroke='" + color + "' stroke-width='" + fmt(s.width) + "'" +
           (s.dashed ? " stroke-dasharray='6,4'" : "") + "/>\n";
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!ax.valid(s.x[i]) || !ay.valid(s.y[i])) continue;
      const double x = ax.map(s.x[i]), y = ay.map(s.y[i]);
      if (i < s.y_error.size() && std::isfinite(s.y_error[i]) && s.y_error[i] > 0) {
        const double y0 = s.y[i] - s.y_error[i], y1 = s.y[i] + s.y_error[i];
        if (ay.valid(y0) && ay.valid(y1))
          o += "<line x1='" + fmt(x) + "' y1='" + fmt(ay.map(y0)) + "' x2='" + fmt(x) + "' y2='" + fmt(ay.map(y1)) +
               "' stroke='" + color + "'/>\n";
      }
      if (s.points) o += "<circle cx='" + fmt(x) + "' cy='" + fmt(y) + "' r='2.6' fill='" + color + "'/>\n";
    }
  }
  o += "</g>\n";
  for (size_t k = 0; k < p.series.size(); ++k) {
    const SvgSeries& s = p.series[k];
    if (s.label.empty()) continue;
    const std::string color = s.color.empty() ? kPalette[k % 8] : s.color;
    const double lx = ax.p0 + 8, ly = ay.p1 + 12 + 13 * legend++;
    if (s.line)
      o += "<line x1='" + fmt(lx) + "' y1='" + fmt(ly - 3) + "' x2='" + fmt(lx + 18) + "' y2='" + fmt(ly - 3) +
           "' stroke='" + color + "' stroke-width='" + fmt(s.width) + "'" + (s.dashed ? " stroke-dasharray='4,3'" : "") +
           "/>\n";
    if (s.points) o += "<circle cx='" + fmt(lx + 9) + "' cy='" + fmt(ly - 3) + "' r='2.6' fill='" + color + "'/>\n";
    o += "<text x='" + fmt(lx + 24) + "' y='" + fmt(ly) + "' font-size='10'>" + escape(s.label) + "</text>\n";
  }
  o += "</g>\n";
}

}  // namespace

std::string render_svg(const SvgFigure& f) {
  if (f.columns < 1) invalid("an SVG figure needs at least 1 column");
  const int n = int(f.panels.size());
  const int cols = std::max(1, std::min(f.columns, n));
  const int rows = (n + cols - 1) / cols;
  const double head = f.title.empty() ? 0 : 30;
  const double W = cols * f.panel_width, H = head + std::max(1, rows) * f.panel_height;
  std::string o = "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='" +
                  fmt(W) + "' height='" + fmt(H) + "' viewBox='0 0 " + fmt(W) + " " + fmt(H) +
                  "' font-family='sans-serif'>\n<rect width='100%' height='100%' fill='white'/>\n";
  if (!f.title.empty())
    o += "<text x='" + fmt(W / 2) + "' y='20' text-anchor='middle' font-size='15' font-weight='bold'>" +
         escape(f.title) + "</text>\n";
  for (int i = 0; i < n; ++i)
    render_panel(o, f.panels[size_t(i)], (i % cols) * f.panel_width, head + (i / cols) * f.panel_height,
                 f.panel_width, f.panel_height);
  return o + "</svg>\n";
}

void write_svg(const std::string& path, const SvgFigure& figure) { write_file_atomically(path, render_svg(figure)); }

std::string render_polylines_svg(const PolylineSet& set, double width, double height, bool use_radii) {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  for (const Vec3& p : set.points) x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  if (set.points.empty()) x0 = y0 = 0, x1 = y1 = 1;
  const double m = 10, span = std::max({x1 - x0, y1 - y0, 1e-300});
  const double k = std::min((width - 2 * m) / std::max(x1 - x0, span * 1e-3), (height - 2 * m) / std::max(y1 - y0, span * 1e-3));
  // Centred in the canvas.
  const double cx = (width - (x1 - x0) * k) / 2, cy = (height - (y1 - y0) * k) / 2;
  auto X = [&](double x) { return cx + (x - x0) * k; };
  auto Y = [&](double y) { return height - cy - (y - y0) * k; };
  std::string o = "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='" +
                  fmt(width) + "' height='" + fmt(height) + "'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (int64_t l = 0; l < set.line_count(); ++l) {
    const int64_t b = set.line_begin(l), e = set.line_end(l);
    if (e - b == 1) {  // a point set (IFS)
      o += "<rect x='" + fmt(X(set.points[size_t(b)][0])) + "' y='" + fmt(Y(set.points[size_t(b)][1])) +
           "' width='1' height='1' fill='#063'/>\n";
      continue;
    }
    if (use_radii) {
      for (int64_t i = b + 1; i < e; ++i)
        o += "<line x1='" + fmt(X(set.points[size_t(i - 1)][0])) + "' y1='" + fmt(Y(set.points[size_t(i - 1)][1])) +
             "' x2='" + fmt(X(set.points[size_t(i)][0])) + "' y2='" + fmt(Y(set.points[size_t(i)][1])) +
             "' stroke='#124' stroke-linecap='round' stroke-width='" + fmt(std::max(0.5, 2 * set.radii[size_t(i)] * k)) + "'/>\n";
      continue;
    }
    std::string path;
    for (int64_t i = b; i < e; ++i)
      path += (i == b ? "M" : " L") + fmt(X(set.points[size_t(i)][0])) + "," + fmt(Y(set.points[size_t(i)][1]));
    o += "<path d='" + path + "' fill='none' stroke='#124' stroke-width='1'/>\n";
  }
  return o + "</svg>\n";
}

}  // namespace ft::io
