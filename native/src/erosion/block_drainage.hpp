// SPDX-License-Identifier: GPL-3.0-or-later
// The maps' drainage area of a large terrain by pieces, so that any window
// of it costs the memory and time of the window plus a halo.
//
// Multiple-flow area has no exact tiling (with divergent flow a tile's
// outflow is a dense linear map of its inflow, and the fill and the flats'
// grading are global), so a terrain wider than DrainageBlocks::whole_side
// is cut along seam lines every `block` samples into pieces: the blocks
// between the lines, the lines' segments between crossings, the crossings.
// Each piece's area is computed on its region (the piece grown by `halo`,
// clipped at a bounded grid's edge, wrapping on a torus, as a bounded grid
// whose edge is an outlet) from the region's own drainage surface, plus the
// water the model's coarse grid sends into the region: each coarse link
// from a cell outside it to one inside adds the outside cell's multiple-flow
// area times that link's share at the lowest cell of the region's first
// ring facing it, near the inside cell's node, at a cell that drains
// inwards; where a river enters, the edge beside it is walled. The lines are pieces of
// their own so that a tile set's tiles, which share their edge samples,
// each need only the pieces inside them when the tile's side is a multiple
// of `block`. A piece's values depend on the piece alone: a window and the
// whole get the same bits.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/landscape_window.hpp"

namespace ft::erosion {

// At 8193^2 the model's cell is 32 samples: blocks of 128 cells, a halo of
// 16 (at 1025^2 in the same proportion a halo of 8 cells left a river that
// ran along a region's edge at an eighth of its area; 16 cells left every
// channel within 10%, tests/native/block_drainage_test.cpp). A tile set's
// tiles of 4096 then need only their own block and lines.
struct DrainageBlocks {
  int32_t block = 4096;       // samples between seam lines
  int32_t halo = 512;         // how far a piece's region reaches past it
  int32_t whole_side = 4097;  // the largest side drained as one grid (about 0.75 GB at 4097^2)
};

// The settings in use (the defaults above). Tests set smaller ones to take
// the pieces' path on small terrains; not thread-safe against running work.
const DrainageBlocks& drainage_blocks();
void set_drainage_blocks(const DrainageBlocks& b);

// Whether g drains by pieces: a side above whole_side and, on a torus, every
// region narrower than the period (else the whole drains as one).
bool drains_by_blocks(const D8Grid& g);

// The pieces along one axis of n samples: [lo, lo + len), in order, lo in [0, n).
struct PieceSpan {
  int64_t lo = 0;
  int32_t len = 0;
};
std::vector<PieceSpan> drainage_spans(int32_t n, bool periodic);

struct PieceRect {
  int64_t x0 = 0, y0 = 0;
  int32_t w = 0, h = 0;
};
// A piece's region: grown by the halo, clipped inside a bounded grid
// (unwrapped on a torus: x0 may be negative).
PieceRect drainage_region(const D8Grid& g, const PieceSpan& x, const PieceSpan& y);

// The coarse grid's flow, once per task: the model's eroded coarse surface
// (before + change; without a coarse-to-fine run, the subgrid's box means
// of the eroded terrain that `eroded` reads), filled and graded as the
// maps' surface, and what each cell gives each neighbour there.
struct CoarseFlow {
  D8Grid g;  // the model's grid (the spacing from the maps' `spacing`)
  std::vector<std::array<double, 8>> given;
  double to_x = 1, to_y = 1;  // a fine column (row) times this: a coarse one
};
CoarseFlow coarse_flow(const LandscapeModel& m, const HeightSource& eroded, double spacing);

// The area of piece `piece` (a rectangle of g) into `out` (piece.w x
// piece.h) from its region's eroded heights `z` and sea flags `sea` (null:
// none), both region.w x region.h.
void piece_drainage_area(const D8Grid& g, const CoarseFlow& f, const PieceRect& piece, const PieceRect& region, const float* z,
                         const uint8_t* sea, float* out, const Progress& progress = Progress());

// Every piece of the whole eroded terrain `z` (g's size, g.sea its sea)
// into area_out, one piece after another.
void block_drainage_area(const D8Grid& g, const CoarseFlow& f, const float* z, float* area_out,
                         const Progress& progress = Progress());

}  // namespace ft::erosion
