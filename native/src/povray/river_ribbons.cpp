// SPDX-License-Identifier: GPL-3.0-or-later
#include "povray/river_ribbons.hpp"

#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/error.hpp"

namespace ft::pov {

Mesh river_ribbons(const PolylineSet& rivers, double flat, int sides, double default_radius) {
  // Local: a unity build puts other files' vector helpers beside these.
  const auto sub = [](const Vec3& a, const Vec3& b) { return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
  const auto add = [](const Vec3& a, const Vec3& b) { return Vec3{a[0] + b[0], a[1] + b[1], a[2] + b[2]}; };
  const auto cross = [](const Vec3& a, const Vec3& b) {
    return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  };
  const auto unit = [](const Vec3& a) {
    const double n = ft::norm(a);
    return n > 0 ? Vec3{a[0] / n, a[1] / n, a[2] / n} : Vec3{0, 0, 0};
  };
  Mesh m;
  std::vector<double> cs(static_cast<size_t>(sides)), sn(static_cast<size_t>(sides));
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    cs[size_t(k)] = std::cos(a), sn[size_t(k)] = std::sin(a);
  }
  std::vector<Vec3> pts;
  std::vector<double> radii;
  for (int64_t line = 0; line < rivers.line_count(); ++line) {
    pts.clear(), radii.clear();
    for (int64_t i = rivers.line_begin(line); i < rivers.line_end(line); ++i) {
      const Vec3& p = rivers.points[size_t(i)];
      if (!pts.empty() && p == pts.back()) continue;
      pts.push_back(p);
      const double r = rivers.radii[size_t(i)];
      radii.push_back(r > 0 ? r : default_radius);
    }
    const size_t n = pts.size();
    if (n < 2) continue;
    if (m.vertex_count() + n * size_t(sides) > size_t(INT32_MAX))
      fail(FT_ERR_TOO_LARGE, "the rivers have too many points for one POV-Ray mesh2 (over 2^31 ribbon vertices)");
    const int32_t first = int32_t(m.vertex_count());
    for (size_t i = 0; i < n; ++i) {
      // The ring is square to the mean of the two segments' directions.
      const Vec3 in = i > 0 ? unit(sub(pts[i], pts[i - 1])) : Vec3{0, 0, 0};
      const Vec3 out = i + 1 < n ? unit(sub(pts[i + 1], pts[i])) : Vec3{0, 0, 0};
      Vec3 t = unit(add(in, out));
      if (ft::norm(t) == 0) t = out[0] || out[1] || out[2] ? out : in;  // a river that turns back
      Vec3 side = unit(cross(t, Vec3{0, 0, 1}));
      if (ft::norm(side) == 0) side = {1, 0, 0};  // a vertical fall: any level axis
      const Vec3 up = cross(side, t);
      const double r = radii[i], h = flat * r;
      for (int k = 0; k < sides; ++k)
        for (int d = 0; d < 3; ++d)
          m.positions.push_back(float(pts[i][size_t(d)] + r * cs[size_t(k)] * side[size_t(d)] +
                                      h * sn[size_t(k)] * up[size_t(d)]));
    }
    // Around a ring, k turns counter-clockwise about -t: a quad (i, k),
    // (i + 1, k), (i + 1, k + 1), (i, k + 1) faces outwards, the first ring
    // in k order faces upstream and the last in reverse order downstream.
    for (size_t i = 0; i + 1 < n; ++i)
      for (int k = 0; k < sides; ++k) {
        const int32_t a = first + int32_t(i) * sides, b = a + sides, k1 = (k + 1) % sides;
        m.face_sizes.push_back(4);
        m.face_indices.insert(m.face_indices.end(), {a + k, b + k, b + k1, a + k1});
      }
    m.face_sizes.push_back(sides);
    for (int k = 0; k < sides; ++k) m.face_indices.push_back(first + k);
    m.face_sizes.push_back(sides);
    const int32_t last = first + int32_t(n - 1) * sides;
    for (int k = sides - 1; k >= 0; --k) m.face_indices.push_back(last + k);
  }
  return m;
}

}  // namespace ft::pov
