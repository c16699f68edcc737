// SPDX-License-Identifier: GPL-3.0-or-later
// Voss's midpoint displacement on the sphere (seed 000), by recursive
// subdivision of the cube-sphere: level 0 is the cube's 8 corners; level
// L + 1 adds, on every face, the centre of each cell (the mean of its 4
// corners) and then the middle of each cell side (the mean of its 2 ends and
// the 2 cell centres beside it; on a cube edge one centre is on each face),
// each displaced by a Gaussian. The flat method's diamond-square on a
// closed surface: every new vertex has 4 parents, so there is no border rule.
//
// The displacement of a vertex at angular distance d (radians) from its
// parents is  sigma_u d^H g :  the flat midpoint's delta = sigma (distance /
// side)^H with the side one radius. d is the cell's size on the cube face
// (2 / 2^L, times sqrt 2 for a cell centre) times the gnomonic map's local
// scale at the vertex, (1 + s^2 + t^2)^(-3/4) (the square root of its area
// element), so a vertex near a cube corner, where cells are 2.3 times
// smaller, is displaced as much as its true spacing asks and the planet's
// variogram is the same function of the angle everywhere.
//
// g is the counter RNG's (Philox, stream kPlanetMidpoint) Gaussian keyed by
// the vertex's integer cube point at its birth level (cube_sphere.hpp); that
// point is the same on the two or three faces an edge or corner vertex lies
// on, and the parents' means are summed in pairs of opposite parents, which
// no face orientation reorders. So a vertex has the same bits on every
// face, in every patch and at every later level, on any thread count.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/progress.hpp"

namespace ft::planet {

struct MidpointConfig {
  double sigma = 4000.0;  // metres (see kMidpointUnit)
  double hurst = 0.8;
  uint64_t seed = 1;
};

// sigma_u = sigma kMidpointUnit: the std of the 8 corners and the scale of
// the displacements. With it the planet's heights spread over the sphere as
// much as the fBm planet's of the same sigma at the default H = 0.8 (std
// 1.03 times the fBm's over 16 seeds), 1.4 times as much at H = 0.5 (the
// fBm's octave sum is normalised, the midpoint's displacements are not):
// planet_midpoint_test HeightsSpreadAsMuchAsTheFbmPlanets.
inline constexpr double kMidpointUnit = 0.2;

// Samples [x0, x1] x [y0, y1] (inclusive; empty if x1 < x0) of one face.
struct FaceRect {
  int64_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  bool empty() const { return x1 < x0 || y1 < y0; }
  int64_t width() const { return x1 - x0 + 1; }
  int64_t height() const { return y1 - y0 + 1; }
  int64_t count() const { return empty() ? 0 : width() * height(); }
  void add(int64_t x, int64_t y);
  void add(const FaceRect& r);
};
using FaceRects = std::array<FaceRect, 6>;

// Bytes midpoint_faces needs besides its outputs (the ancestors of the rects).
uint64_t midpoint_work_bytes(int level, const FaceRects& rects);

// The samples of `rects` (per face, at `level`) into out[f] (rects[f]'s
// samples row by row, metres above the radius, no sea): computed from the
// ancestors of just those samples, level by level, so a small patch at level
// 23 costs about its own size. Checks the memory first; reports progress.
void midpoint_faces(const MidpointConfig& c, int level, const FaceRects& rects, const std::array<float*, 6>& out,
                    int threads, const Progress& progress);

}  // namespace ft::planet
