// SPDX-License-Identifier: GPL-3.0-or-later
// A set of polylines sharing one vertex array: float64 xyz plus a radius per
// vertex; line i spans [offsets[i], offsets[i + 1]).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ft {

using Vec3 = std::array<double, 3>;

inline double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

struct PolylineSet {
  std::vector<Vec3> points;
  std::vector<double> radii;       // same length as points
  std::vector<int64_t> offsets{0}; // line_count + 1 entries

  int64_t line_count() const noexcept { return int64_t(offsets.size()) - 1; }
  int64_t vertex_count() const noexcept { return int64_t(points.size()); }
  // Appends a vertex to the line being built.
  void add(const Vec3& p, double radius = 0.0) {
    points.push_back(p);
    radii.push_back(radius);
  }
  // Ends the line being built (an empty line is dropped).
  void end_line() {
    if (int64_t(points.size()) > offsets.back()) offsets.push_back(int64_t(points.size()));
  }
  int64_t line_begin(int64_t i) const { return offsets[size_t(i)]; }
  int64_t line_end(int64_t i) const { return offsets[size_t(i) + 1]; }
};

}  // namespace ft
