// SPDX-License-Identifier: GPL-3.0-or-later
// Drainage across flats for the maps: each flat graded by random passage
// times from its outlets.
//
// A filled depression, or a plain, is exactly flat: its heights say nothing
// about where the water goes. Priority-Flood+epsilon graded it by Chebyshev
// distance from its spill, so the maps' multiple flow crossed it along rows
// and diagonals: straight streaks in the drainage area and in the colours
// that read it. Here the heights stay as they are and a flat gets a second
// key, the gradient towards lower terrain of Garbrecht & Martz (1997) and
// Barnes, Lehman & Mulla (2014, "An efficient assignment of drainage
// direction over flat surfaces in raster digital elevation models"), but
// measured in random step costs instead of grid steps (as the eroder's
// fills grade a flat by random float steps, flow_graph.hpp): the shortest
// ways to the outlets wander and join as water's do on flat ground, and
// their mean course is still the shortest. (Barnes et al.'s second
// gradient, away from higher ground, combined as theirs (2 x towards -
// away), was tried: with random costs it drew straight lines down the
// middle of each flat, 4-7% of the flats' cells on straight runs of 16 or
// more against 0.2-1.5% without (the test lake and the eroded default
// mountain), and it costs a second search; on grid steps alone both
// gradients left 98% of the lake on such runs, as the epsilon fill did.)
#pragma once

#include <cstdint>

#include "core/buffer.hpp"
#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"

namespace ft::erosion {

struct FlatGrading {
  // Per cell, bit k: neighbour k is of the same height and one of the two is
  // on a flat (no lower neighbour, not a base level). Non-zero off the
  // flats: an outlet of one (a cell that drains, or a base level, beside a
  // flat cell of its height).
  Buffer<uint8_t> level;
  // On a flat, the passage time to its nearest outlet, 8 or more; 0 at the
  // outlets and off the flats. A flat cell gives to its level neighbours
  // whose key is lower, in proportion to the difference: its nearest way
  // out is lower by that step's cost.
  Buffer<int32_t> key;
  int64_t flat_cells = 0;  // 0: the rest is empty
};

// Grades the flats of `z`, which must drain except across flats (after
// fill_closed_basins with `flat`): every cell that is not a base level
// reaches one by a path that never rises. A step costs the two cells'
// factors added (times sqrt 2 diagonally), each an integer uniform in 4 ..
// 19 from the counter RNG (stream kFlatRouting, positions relative to
// `sink` on a torus, so a shifted torus grades alike). One serial search in
// a fixed order: the same bits on any thread count. `progress` hears the
// share done, every 64th of the grid at most; a cancel stops it.
// With `frame` (may be null) g is a rectangle of a larger grid and draws
// the numbers of its cells' positions there (frame->x0 + x, frame->y0 + y
// in frame->whole), so that overlapping rectangles grade a shared flat alike.
struct FlatFrame {
  D8Grid whole;
  int64_t x0 = 0, y0 = 0;
};
void resolve_flats(const D8Grid& g, const float* z, int32_t sink, FlatGrading& flats,
                   const Progress& progress = Progress(), const FlatFrame* frame = nullptr);

}  // namespace ft::erosion
