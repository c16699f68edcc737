// SPDX-License-Identifier: GPL-3.0-or-later
// Single-flow (D8) routing, in the shape of fastscapelib's flow graph:
// receivers by steepest descent (or Rho8's randomised descent), the stack
// order of Braun & Willett (2013), drainage area accumulated down the stack,
// and pit resolution by Priority-Flood+epsilon (Barnes, Lehman & Mulla 2014). Eroders take a
// FlowGraph and reuse it; the arrays are allocated once and refilled each
// time step, so a step allocates nothing.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "core/rng.hpp"
#include "erosion/d8_grid.hpp"

namespace ft::erosion {

// Runs of the stack (a fixed number, so results never depend on the
// thread count).
inline constexpr int32_t kStackChunks = 64;

struct FlowGraph {
  std::vector<int32_t> receiver;   // receiver[i] == i: a base level (outlet or declared sink)
  std::vector<float> length;       // distance to the receiver (0 at base levels)
  std::vector<int32_t> stack;      // every cell after its receiver
  std::vector<int32_t> donor_start, donors;  // donors of i: donors[donor_start[i] .. donor_start[i+1])
  std::vector<int32_t> work;       // scratch
  // The stack in runs of whole trees (independent: they go to threads):
  // run c is stack[chunk_start[c] .. chunk_start[c + 1]).
  std::vector<int32_t> bases, chunk_start;
  // Scratch of build_stack: each run's part of the stack and its search
  // stack (kept, so that a step allocates nothing).
  std::vector<std::vector<int32_t>> parts, todo;
  int64_t pits = 0;                // interior cells without a lower neighbour at the last routing
  // Scratch of fill_pits_locally: visit stamps (one number per search, so
  // nothing is cleared between searches) and the cells of one depression.
  std::vector<uint32_t> seen, closed;
  uint32_t stamp = 0;
  std::vector<int32_t> region;
  std::vector<int32_t> changed;  // cells the last fill_pits_locally raised
  // Rho8 (see draw_rho8): one uniform number in (0, 1) per cell for this
  // step, read by the routing and the fills; empty: plain D8 and one float
  // step per filled cell.
  std::vector<float> random;
};

// The cell a periodic grid drains to: the lowest sample (the first in row
// order among equals), so that a torus has one outlet.
int32_t periodic_sink(const D8Grid& g, const float* z);

// Rho8 (Fairfield & Leymarie 1991): draws each cell's random number r,
// uniform in (0, 1), for the routings and fills that follow. D8 sends the
// water of a plane whose fall line lies between a row and a diagonal all
// along the nearer grid direction: one long straight channel across a gentle
// slope. Rho8 takes a diagonal's run as 2 - r spacings instead of sqrt 2, so
// the diagonal wins with probability tan(aspect): paths zigzag along the fall
// line on average and converge where they meet. The fills raise a flat by
// 1 to 4 float steps per cell by r instead of one, in order of height: a
// flat drains along wandering paths to its spill instead of straight rows
// and diagonals (a flood in FIFO order grades a flat by Chebyshev distance,
// and the valleys that later cut through it were straight lines). r comes
// from the counter RNG at (stream kFluvialRouting, level `step`, the cell's
// position relative to `origin`): the same on any thread count, and a
// periodic grid keyed from its sink (the lowest sample) draws the same
// numbers for the same terrain shifted across its edges.
void draw_rho8(const D8Grid& g, int32_t origin, uint32_t step, FlowGraph& graph);

// One number uniform in (0, 1) per cell into `out` (resized to the grid),
// from the counter RNG at (`stream`, `level`, the cell's position relative to
// `origin`, or to the corner when it is negative), as draw_rho8 draws them.
void draw_cell_uniforms(const D8Grid& g, int32_t origin, uint32_t level, Stream stream, std::vector<float>& out);
// Row y of what draw_cell_uniforms draws, into row[0 .. width).
void draw_row_uniforms(const D8Grid& g, int32_t origin, uint32_t level, Stream stream, int32_t y, float* row);

// Rho8's weight of a diagonal drop: 1 / rho, rho = 2 - r uniform in (1, 2),
// the diagonal's run in spacings. On a plane whose fall line makes the angle
// a (0 <= a <= 45 degrees) with a row, the diagonal's drop per run
// (cos a + sin a) / rho beats the row's cos a when rho < 1 + tan a: with
// probability tan a, so a path's mean step (1, tan a) lies along the fall
// line (Fairfield & Leymarie 1991).
// Kept strictly above 1/2, so that every positive drop stays positive: for
// r < 2^-24, 2 - r rounds to 2 and the weight to exactly 1/2, and half the
// smallest subnormal drop (2^-149) rounds to 0. Erosion wears a plain
// towards a base level of 0 into subnormal heights; a cell whose only lower
// neighbours were diagonals 2^-149 below then had no positive drop, so the
// routing called it a pit, while the fills (which compare heights) saw it
// drain and left it alone: route_and_fill looped forever (issue 24's hang).
inline float rho8_diagonal_weight(float r) { return std::max(1.0f / (2.0f - r), 0x1.000002p-1f); }

// The numbers draw_row_uniforms gives columns x0 .. x0 + count - 1 (wrapped
// into the grid) of row y, with the origin at (ox, oy): for a region of the
// grid (erosion/detail_run.hpp), keyed by position as the whole draws them.
void draw_uniforms_at(const D8Grid& g, int64_t ox, int64_t oy, uint32_t level, Stream stream, int64_t y, int64_t x0,
                      int32_t count, float* out);

// Receivers by steepest descent (ties: the first direction in kDx order),
// diagonal drops over a run of 2 - r spacings when graph.random is drawn
// (Rho8), else sqrt 2 (D8).
// Bounded grids: every edge cell is a base level. Periodic grids: `sink` is.
// Either way, so is every sea cell (g.sea).
// An interior cell with no lower neighbour becomes its own receiver and is
// counted in graph.pits. Rows in parallel: the result does not depend on the
// thread count.
void route_steepest(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph);

// Donor lists by an O(n) count and the stack by depth-first search from the
// base levels in index order (Braun & Willett 2013, section 2.2), the trees
// in kStackChunks runs searched in parallel.
void build_stack(const D8Grid& g, FlowGraph& graph);

// Drainage area in world units^2 (each cell spacing^2, including its own),
// summed down the stack; exact for areas below 2^53 cells.
void accumulate_area(const D8Grid& g, const FlowGraph& graph, std::vector<double>& area);

// Raises every depression to the lowest spill level plus one float step per
// cell (Priority-Flood+epsilon, Barnes et al. 2014, Algorithm 3 with the pit
// queue), so every cell then has a strictly lower neighbour on a path to an
// edge (bounded) or to `sink` (periodic). Returns the number of cells raised.
// With `random` (one number in (0, 1) per cell, see draw_rho8) a raised cell
// is 1 to 4 float steps above the cell it was reached from, and raised cells
// are visited in order of height, not first in first out. `progress` hears
// the share of cells done (priority_flood).
int64_t fill_depressions(const D8Grid& g, float* z, int32_t sink, const float* random = nullptr,
                         const Progress& progress = Progress());

// What fill_depressions does without `random` (every depression raised to
// its lowest spill plus a float step per cell, so every cell that is not a
// base level then has a strictly lower neighbour), visiting only the cells
// that do not drain already: those with a strictly falling path to a base
// level are found first, breadth first, and stay as they are (as in
// fill_depressions); the flood starts from them. Equal heights may be taken
// in another order than fill_depressions takes them, so a flat may be
// graded differently. On an eroded 4097^2 terrain, where 56% of the cells
// drain, it takes about half the time. Returns the number of cells raised;
// `progress` hears both parts. `flat`: every depression is raised exactly to
// its spill, with no float steps (Priority-Flood without the epsilon), into
// flats that resolve_flats (flat_resolution.hpp) grades; these heights are
// unique, whatever the order of equal heights.
int64_t fill_closed_basins(const D8Grid& g, float* z, int32_t sink, const Progress& progress = Progress(),
                           bool flat = false);

// Fills the depression of every pit of the last routing, one at a time in
// index order, by a Priority-Flood+epsilon restricted to that depression: a
// flood from the pit finds the lowest spill cell (one with a lower cell
// outside the depression, or an outlet), then the depression is raised to
// drain to it. Cost: the depressions' size, not the grid's (diffusion leaves
// many small pits each step; a global fill each step would dominate). The
// raised cells are listed in graph.changed. graph.random, when drawn, grades
// the fill as in fill_depressions.
void fill_pits_locally(const D8Grid& g, float* z, int32_t sink, FlowGraph& graph);

// Routes again the cells in graph.changed and their neighbours (the only
// ones whose steepest descent a local fill can change), keeping graph.pits.
void reroute_changed(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph);

// Route; while pits remain, fill them locally and route the raised cells
// again (a global fill and a full routing when pits are more than one cell
// in 16, or after a few rounds). Afterwards every cell that is not a base
// level has a strictly lower neighbour (what multiple_flow_area needs).
// `progress` moves through a global fill (the long part on a large grid).
void route_and_fill(const D8Grid& g, float* z, int32_t sink, FlowGraph& graph, const Progress& progress = Progress());

// The usual sequence for an eroder: route_and_fill, then the stack.
void route_filled(const D8Grid& g, float* z, int32_t sink, FlowGraph& graph, const Progress& progress = Progress());

}  // namespace ft::erosion
