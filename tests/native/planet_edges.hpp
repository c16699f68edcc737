// SPDX-License-Identifier: GPL-3.0-or-later
// The steps across the cube-sphere's edges, shared by the fBm and midpoint
// no-seam tests: for every edge sample e of a level with N = n shared by
// faces A and B (not a corner, both orderings), e, the samples a1 and a2 one
// and two steps inside A (e - 2 n_B, e - 4 n_B in cube units) and b1 one
// step inside B (e - 2 n_A).
#pragma once

#include <gtest/gtest.h>

#include "planet/cube_sphere.hpp"

namespace ft::planet {

template <class Visit>
void for_each_edge_step(int64_t n, Visit&& visit) {
  for (int a = 0; a < 6; ++a)
    for (int64_t j = 1; j < n; ++j)
      for (int side = 0; side < 4; ++side) {
        const int64_t i = side < 2 ? (side == 0 ? 0 : n) : j, jj = side < 2 ? j : (side == 2 ? 0 : n);
        const CubePoint e = cube_point(a, i, jj, n);
        for (int b = 0; b < 6; ++b) {
          int64_t bi, bj;
          if (b == a || !face_sample(e, b, n, &bi, &bj)) continue;
          const auto na = face_normal(a), nb = face_normal(b);
          const CubePoint a1{e.x - 2 * nb[0], e.y - 2 * nb[1], e.z - 2 * nb[2]};
          const CubePoint a2{e.x - 4 * nb[0], e.y - 4 * nb[1], e.z - 4 * nb[2]};
          const CubePoint b1{e.x - 2 * na[0], e.y - 2 * na[1], e.z - 2 * na[2]};
          ASSERT_TRUE(face_sample(a1, a, n, &bi, &bj));
          ASSERT_TRUE(face_sample(b1, b, n, &bi, &bj));
          visit(e, a1, a2, b1);
        }
      }
}

}  // namespace ft::planet
