// SPDX-License-Identifier: GPL-3.0-or-later
// The arithmetic of one point of each diamond-square step, shared by every
// refiner (the whole grid in place, and windows of it): a point computed in
// either gets the same bits because it is computed here.
//
// Square step: a centre is the mean of its 4 corners plus delta g. Diamond
// step: an edge midpoint is the mean of its 4 axis neighbours plus delta g;
// on a non-periodic border it has 3, summed in the order left, right, up,
// down (a periodic border wraps around and is an ordinary interior point).
#pragma once

#include <cstdint>

namespace ft::terrain::detail {

// Centres row[x0 + i big] for i < count, from the rows `up` and `dn` half a
// cell above and below: 0.25 ((up[x-h] + up[x+h]) + (dn[x-h] + dn[x+h])) + delta g[i].
void square_row(float* row, const float* up, const float* dn, int x0, int count, int big, int half, float delta,
                const float* g);

// Edge midpoints row[x0 + i big] with all 4 neighbours present:
// 0.25 ((row[x-h] + row[x+h]) + (up[x] + dn[x])) + delta g[i].
void diamond_interior(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                      float delta, const float* g);

// The loops behind square_row and diamond_interior: portable C++ compiled
// for AVX2 and baseline x86-64 (midpoint_steps.cpp), and for strides big
// 2, 4 and 8 (steps_avx512_stride; half = big / 2) written for AVX-512
// (midpoint_steps_avx512.cpp), taken where steps_avx512(). All give the
// same bits (tests compare them).
void square_row_portable(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                         float delta, const float* g);
void diamond_interior_portable(float* row, const float* up, const float* dn, int x0, int count, int big, int half,
                               float delta, const float* g);
bool steps_avx512();
bool steps_avx512_stride(int big);
void square_row_avx512(float* row, const float* up, const float* dn, int x0, int count, int big, float delta,
                       const float* g);
void diamond_interior_avx512(float* row, const float* up, const float* dn, int x0, int count, int big, float delta,
                             const float* g);

// The Philox row of a point of the stage with spacing `half` (in the finest
// grid's units) on row y: its row in that stage's own grid. Columns are
// likewise counted in the stage's cells. Stage s's draws are then the same
// whatever the levels below it, so a terrain of levels L is the terrain of
// levels L + k at its nodes, bit for bit (keyed by y itself, every stage's
// draws moved when the grid grew: levels 7 and 9 correlated 0.17 there).
inline uint32_t stage_row(int64_t y, int64_t half) { return uint32_t(y / half); }

// A border point's mean of the k (3, or 2 at a corner) neighbours present,
// in the order left, right, up, down; a missing neighbour is passed as
// nullptr.
inline float border_mean(const float* left, const float* right, const float* up, const float* down) {
  float sum = 0.0f;
  int k = 0;
  if (left) sum += *left, ++k;
  if (right) sum += *right, ++k;
  if (up) sum += *up, ++k;
  if (down) sum += *down, ++k;
  return sum / float(k);
}

// The 4-neighbour mean of the diamond step (periodic borders use it with
// wrapped neighbours).
inline float interior_mean(float left, float right, float up, float down) {
  return 0.25f * ((left + right) + (up + down));
}

}  // namespace ft::terrain::detail
