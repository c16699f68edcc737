// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/polyline_stats.hpp"

#include <cmath>

#include "core/error.hpp"

namespace ft::analysis {
namespace {

double dist(const Vec3& a, const Vec3& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

void check_line(const PolylineSet& set, int64_t line) {
  if (line < 0 || line >= set.line_count())
    invalid("line " + std::to_string(line) + " does not exist (the set has " + std::to_string(set.line_count()) +
            " lines)");
}

}  // namespace

LineStats line_stats(const PolylineSet& set, int64_t line) {
  check_line(set, line);
  const int64_t b = set.line_begin(line), e = set.line_end(line);
  LineStats s;
  s.vertices = e - b;
  for (int64_t i = b + 1; i < e; ++i) s.length += dist(set.points[size_t(i - 1)], set.points[size_t(i)]);
  if (s.vertices < 2) return s;
  const Vec3& p1 = set.points[size_t(b)];
  const Vec3& pn = set.points[size_t(e - 1)];
  s.chord = dist(p1, pn);
  if (!(s.chord > 0)) return s;
  const Vec3 u{(pn[0] - p1[0]) / s.chord, (pn[1] - p1[1]) / s.chord, (pn[2] - p1[2]) / s.chord};
  double max_dev = 0, sum_dev = 0;
  for (int64_t i = b; i < e; ++i) {
    const Vec3& p = set.points[size_t(i)];
    const Vec3 w{p[0] - p1[0], p[1] - p1[1], p[2] - p1[2]};
    // |w x u|: the distance from the chord's line.
    const double cx = w[1] * u[2] - w[2] * u[1], cy = w[2] * u[0] - w[0] * u[2], cz = w[0] * u[1] - w[1] * u[0];
    const double dev = std::sqrt(cx * cx + cy * cy + cz * cz) / s.chord;
    max_dev = std::max(max_dev, dev);
    sum_dev += dev;
  }
  s.eta = max_dev;
  s.chi = sum_dev / double(s.vertices);
  s.gamma = s.length / s.chord;
  return s;
}

double mass_dimension(const PolylineSet& set, int64_t line) {
  check_line(set, line);
  const int64_t b = set.line_begin(line), e = set.line_end(line);
  if (e - b < 3) return NAN;
  double fine = 0, coarse = 0;
  for (int64_t i = b + 1; i < e; ++i) fine += dist(set.points[size_t(i - 1)], set.points[size_t(i)]);
  int64_t i = b;
  for (; i + 2 < e; i += 2) coarse += dist(set.points[size_t(i)], set.points[size_t(i + 2)]);
  if (i + 1 < e) coarse += dist(set.points[size_t(i)], set.points[size_t(e - 1)]);  // odd count: last piece
  if (!(coarse > 0)) return NAN;
  const double l = std::log2(fine / coarse);
  return l < 1 ? 1.0 / (1.0 - l) : NAN;
}

PolylineMeasures measure_polylines(const PolylineSet& set, const BoxCountOptions& box) {
  PolylineMeasures m;
  if (set.line_count() == 0) invalid("the polyline set is empty");
  m.main = line_stats(set, 0);
  m.mass_dimension = mass_dimension(set, 0);
  for (int64_t l = 0; l < set.line_count(); ++l) m.total_length += line_stats(set, l).length;
  try {
    m.box = box_counting_dimension(set, box);
    m.box_ok = true;
  } catch (const Error& e) {
    if (e.status() != FT_ERR_INVALID_ARGUMENT) throw;
    m.box_error = e.what();
  }
  return m;
}

}  // namespace ft::analysis
