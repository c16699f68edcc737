// SPDX-License-Identifier: GPL-3.0-or-later
// The landscape model's detail run (landscape.cpp) on a region of the
// terrain's grid, where every sample depends only on the samples within a
// fixed reach of it: so any window of the result, computed on the window
// grown by that reach, has the bits of the whole (a tile set has no seams),
// and the whole itself is computed in bands of bounded memory.
//
// A step, as the model's own (routing, detachment, deposition, creep), with
// the global parts bounded:
//   routing     steepest descent (Rho8) on the step's heights; a pit keeps
//               its water (no routing over depressions: the model's run on
//               its own grid has drained the landform's lakes);
//   discharge   the rain of the cells whose way down reaches a cell within
//               kHops steps (the detail run resolves flow paths below the
//               model's cell; the model carries the long ones);
//   detachment  stream power solved implicitly along the next kCutHops
//               receivers of each cell (the chain's last at its start height);
//   deposition  what was detached flows down kHops receivers at most, each
//               cell laying G x its own rain / Q of what passes (as the
//               model), never above the cell it came from less a fan slope;
//               a pit fills up to its lowest neighbour, keeping the share
//               min(1, G) as the model's lakes do; what goes further leaves;
//   creep       hillslope diffusion of what the run did (not of the rock's
//               texture), as a Gaussian of the implicit step's variance
//               (three box filters a side, closed at a bounded grid's edges).
// Every sum is taken in an order fixed by the samples' positions, so the
// bits do not depend on the region or the thread count.
#pragma once

#include <cstdint>

#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/erosion.hpp"

namespace ft::erosion {

// A rectangle of the terrain's grid `whole` (its size, spacing and whether it
// wraps; its sea is not read): samples [x0, x0 + width) x [y0, y0 + height)
// in the whole's coordinates. On a periodic grid they may run past its edges
// (positions wrap); on a bounded one they lie inside it.
struct Region {
  D8Grid whole;
  int64_t x0 = 0, y0 = 0;
  int32_t width = 0, height = 0;

  size_t size() const { return size_t(width) * size_t(height); }
  // The whole's column and row of local sample (x, y), wrapped on a torus.
  int64_t column(int32_t x) const { return wrap(x0 + x, whole.width); }
  int64_t row(int32_t y) const { return wrap(y0 + y, whole.height); }
  // A bounded grid's own edge (a base level), not the region's.
  bool on_whole_edge(int32_t x, int32_t y) const {
    if (whole.periodic) return false;
    const int64_t gx = x0 + x, gy = y0 + y;
    return gx == 0 || gy == 0 || gx == whole.width - 1 || gy == whole.height - 1;
  }

 private:
  bool periodic() const { return whole.periodic; }
  int64_t wrap(int64_t v, int64_t n) const { return whole.periodic ? ((v % n) + n) % n : v; }
};

// The region's inputs besides the heights, indexed like them (null: none).
struct DetailInputs {
  const float* mask = nullptr;   // the erosion mask at each sample
  const float* rain = nullptr;   // the rain map at each sample
  const uint8_t* sea = nullptr;  // 1 on the sea's samples (base levels that stay)
  // Rho8's numbers are keyed by the position relative to this sample of the
  // whole (a torus: the model's sink, so a shifted torus draws alike).
  int64_t origin_x = 0, origin_y = 0;
};

// How far (in samples) a detail run of `years` in `steps` steps reads around
// a sample: a region computes its samples this far inside its own edges
// (where they are not the whole's edges) with the bits of the whole.
int32_t detail_reach(const D8Grid& g, const ErosionConfig& c, double years, int32_t steps);

// The detail run on region `r`: z (r.size() heights, in place) for `years`
// in `steps` steps; creep acts on z less its heights at the start (the
// rock's texture, see landscape.cpp). Samples within detail_reach of the
// region's edges that are not the whole's edges are left with heights of
// no meaning. `progress` hears each step.
void detail_run(const Region& r, const ErosionConfig& c, double years, int32_t steps, const DetailInputs& in, float* z,
                const Progress& progress);

}  // namespace ft::erosion
