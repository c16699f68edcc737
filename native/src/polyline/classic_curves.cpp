// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/classic_curves.hpp"

#include <cmath>

#include "core/error.hpp"

namespace ft::polyline {
namespace {

// A turtle in the local frame of the base segment: unit steps in the
// direction angle (in multiples of 60 degrees), mapped onto a -> b at the end
// so the last vertex is b exactly.
struct Turtle {
  Vec3* out;
  int64_t n = 0;
  int heading = 0;  // multiples of 60 degrees, mod 6
  double x = 0, y = 0;
  void step(double len) {
    static const double kCos[6] = {1, 0.5, -0.5, -1, -0.5, 0.5};
    static const double kSin[6] = {0, 0.86602540378443865, 0.86602540378443865, 0, -0.86602540378443865,
                                   -0.86602540378443865};
    const int h = ((heading % 6) + 6) % 6;
    x += len * kCos[h];
    y += len * kSin[h];
    out[n++] = {x, y, 0.0};
  }
  void turn(int sixths) { heading += sixths; }
};

// Local (u along ab, v to the left of ab, both in units of |ab|) -> world.
void map_to_segment(const Vec3& a, const Vec3& b, Vec3* pts, int64_t n) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  for (int64_t i = 0; i < n; ++i) {
    const double u = pts[i][0], v = pts[i][1];
    pts[i] = {a[0] + u * dx - v * dy, a[1] + u * dy + v * dx, a[2] + u * dz};
  }
  pts[0] = a;
  pts[n - 1] = b;
}

void koch_rec(Turtle& t, int depth, double len) {
  if (depth == 0) return t.step(len);
  koch_rec(t, depth - 1, len / 3);
  t.turn(1);
  koch_rec(t, depth - 1, len / 3);
  t.turn(-2);
  koch_rec(t, depth - 1, len / 3);
  t.turn(1);
  koch_rec(t, depth - 1, len / 3);
}

// angle = +1 or -1 sixth of a turn; the classic arrowhead recursion.
void arrowhead_rec(Turtle& t, int depth, double len, int angle) {
  if (depth == 0) return t.step(len);
  arrowhead_rec(t, depth - 1, len / 2, -angle);
  t.turn(angle);
  arrowhead_rec(t, depth - 1, len / 2, angle);
  t.turn(angle);
  arrowhead_rec(t, depth - 1, len / 2, -angle);
}

int64_t ipow(int64_t b, int e) {
  int64_t r = 1;
  while (e-- > 0) r *= b;
  return r;
}

}  // namespace

int64_t koch_vertex_count(int depth) {
  check_int_range("depth", depth, 0, kMaxKochDepth);
  return ipow(4, depth) + 1;
}

int64_t arrowhead_vertex_count(int depth) {
  check_int_range("depth", depth, 0, kMaxArrowheadDepth);
  return ipow(3, depth) + 1;
}

void koch_curve(const Vec3& a, const Vec3& b, int depth, Vec3* out) {
  const int64_t n = koch_vertex_count(depth);
  Turtle t{out};
  out[t.n++] = {0, 0, 0};
  koch_rec(t, depth, 1.0);
  map_to_segment(a, b, out, n);
}

void arrowhead_curve(const Vec3& a, const Vec3& b, int depth, Vec3* out) {
  const int64_t n = arrowhead_vertex_count(depth);
  Turtle t{out};
  out[t.n++] = {0, 0, 0};
  // Odd depths start 60 degrees up so that the curve still ends on the base.
  if (depth % 2 == 0) {
    arrowhead_rec(t, depth, 1.0, 1);
  } else {
    t.turn(1);
    arrowhead_rec(t, depth, 1.0, -1);
  }
  map_to_segment(a, b, out, n);
}

}  // namespace ft::polyline
