// SPDX-License-Identifier: GPL-3.0-or-later
// Nikulin's fractal polyline (seed 003, FPLrec): recursive orthogonal
// midpoint displacement of a segment a -> b,
//   V = b - a;  stop (emit b) when r = 0 or |V| < delta;
//   c = a + 0.5 V;  d = c + rf(lambda) * Lrot(V),  Lrot([x, y]) = [-y, x];
//   FPLrec(a, d, r - 1);  FPLrec(d, b, r - 1).
// rf is urf(s), uniform on [-s, s], or nrf(sigma), normal; the displacement is
// thus rf * |V| perpendicular to the segment. The end points survive exactly.
//
// Randomness is keyed by position, not by draw order: the midpoint of node j
// (0 .. 2^l - 1, left to right) of recursion level l (0 = the whole segment)
// of line `line_id` takes index j of Counter{line_id, l, Stream::kPolyline}.
// So the breadth-first fill (min_length = 0), the depth-first recursion
// (min_length > 0) and any future parallel split give the same vertices.
//
// Variants on the same engine:
//   3D: the displacement rf * |V| points in a random direction perpendicular
//       to V (angle uniform, Counter{line_id, l + 64, kPolyline}), or, with a
//       plane normal n, along unit(n x V) (n = z gives the 2D rule);
//   dragon (Harter-Heighway, seed 002): rf replaced by the deterministic
//       +1/2 for even j and -1/2 for odd j (left first, then alternating).
#pragma once

#include <cstdint>
#include <functional>

#include "core/polyline_set.hpp"
#include "core/progress.hpp"

namespace ft::polyline {

enum class FplRng : int { kUniform = 0, kNormal = 1 };
enum class FplRule : int { kRandom = 0, kDragon = 1 };

// Node j of level l uses Philox block j / 4 (32 bits): j < 2^34, so levels 0..33.
inline constexpr int kMaxFplDepth = 34;

struct FplConfig {
  FplRng rng = FplRng::kUniform;
  FplRule rule = FplRule::kRandom;
  double spread = 0.1;      // s (uniform half-width) or sigma (normal std), per unit |V|
  int depth = 8;            // r
  double min_length = 0.0;  // delta: segments shorter than this are not split
  uint64_t seed = 1;
  bool three_d = false;
  Vec3 plane_normal{0, 0, 0};  // 3D only; all zero: random direction per midpoint
  int threads = 0;             // 0: all cores; the output never depends on it
  Progress progress;
};

// Called for every split: level l, node j, the segment a -> b and the new
// midpoint d (used by branching lightning).
using FplSplitVisitor =
    std::function<void(int level, uint64_t node, const Vec3& a, const Vec3& b, const Vec3& d)>;

// Vertices of one segment's FPL including both ends: 2^depth + 1 when
// min_length is 0; otherwise counted by running the recursion without
// storing (exact, since the draws depend only on position). Throws
// FT_ERR_TOO_LARGE when the count exceeds the memory cap.
int64_t fpl_vertex_count(const FplConfig& c, const Vec3& a, const Vec3& b, uint32_t line_id);

// Writes fpl_vertex_count(...) vertices into out (out[0] = a, last = b).
// The visitor, if given, is called for the splits of levels < visit_levels.
void fpl_segment(const FplConfig& c, const Vec3& a, const Vec3& b, uint32_t line_id, Vec3* out,
                 const FplSplitVisitor* visitor = nullptr, int visit_levels = 0);

}  // namespace ft::polyline
