// SPDX-License-Identifier: GPL-3.0-or-later
// The classic deterministic fractal curves of seed 002, each drawn on a base
// segment a -> b (the curve starts at a and ends at b):
//   Koch curve: each segment becomes 4 of a third, the middle two forming an
//     equilateral bump to the left; 4^depth segments, D = log 4 / log 3.
//   Sierpinski arrowhead: the L-system A -> B-A-B, B -> A+B+A with 60 degree
//     turns; 3^depth segments of length 2^-depth, D = log 3 / log 2.
// (The Harter-Heighway dragon is the FPL engine with a deterministic rule,
// see fpl.hpp.)
#pragma once

#include <cstdint>

#include "core/polyline_set.hpp"

namespace ft::polyline {

inline constexpr int kMaxKochDepth = 15;        // 4^15 = 1.07e9 segments
inline constexpr int kMaxArrowheadDepth = 19;   // 3^19 = 1.16e9 segments

// Vertex counts of one segment's curve: 4^depth + 1 and 3^depth + 1.
int64_t koch_vertex_count(int depth);
int64_t arrowhead_vertex_count(int depth);

// Write the curve's vertices (including a and b) into out, which holds
// koch_vertex_count(depth) / arrowhead_vertex_count(depth) entries. z is
// interpolated linearly between a and b; the curve lies in the x,y plane.
void koch_curve(const Vec3& a, const Vec3& b, int depth, Vec3* out);
void arrowhead_curve(const Vec3& a, const Vec3& b, int depth, Vec3* out);

}  // namespace ft::polyline
