// SPDX-License-Identifier: GPL-3.0-or-later
// Routing over depressions without filling them: the basin graph of
// Cordonnier, Bovy & Braun (2019, "A versatile, linear complexity algorithm
// for flow routing in topographies with depressions", Earth Surf. Dynam. 7),
// as fastscapelib resolves sinks ("mst_kruskal" + "carve").
//
// The steepest-descent receivers split the grid into basins, one per base
// level or pit. Neighbouring basins meet at passes (the lower of a pair's
// two heights to be crossed is the higher of its cells). The minimum spanning
// tree of the basins, with every base level's basin as one root, is where
// water spills: each pit drains across the pass to its parent, the path from
// the pass down to the pit reversed ("carved") so that the water leaves
// through the pass cell. A depression's water surface is the highest pass on
// its way to a base level: what Priority-Flood would fill it to, found
// without visiting the lake's cells in order of height.
//
// Against route_filled (a Priority-Flood+epsilon of a copy, then routing on
// it), the landscape model's step costs a routing, two stack builds and one
// scan of the basins' cells, with no heap: a fractal terrain has lakes on
// half its cells, and refilling them every step was most of the model's time.
#pragma once

#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/flow_graph.hpp"

namespace ft::erosion {

// A pass between two basins: `inside` (in the basin that spills, once
// oriented) and `outside` are neighbours; `height` = max of their heights.
struct BasinLink {
  float height;
  float tie;  // Rho8's number at the pass (0 for D8): equal passes, a random tree
  // The pass's cells' positions relative to the periodic sink (a bounded
  // grid: their indices), lower first: the last of the order's keys, so
  // that a torus shifted across its edges orders its passes alike.
  uint32_t first, second;
  int32_t cell_a, cell_b;  // the pass's cells, in basins a and b
  int32_t a, b;            // the basins' nodes (0: every base level's basin)

  // The order of passes (the tree takes the lowest): a strict total order
  // of the pair of cells, so the tree does not depend on how the basins are
  // numbered or scanned.
  bool operator<(const BasinLink& o) const {
    if (height != o.height) return height < o.height;
    if (tie != o.tie) return tie < o.tie;
    return first != o.first ? first < o.first : second < o.second;
  }
};

// Scratch of route_over_depressions (kept between steps: a step allocates
// nothing once the sizes settle).
struct BasinGraph {
  std::vector<int32_t> node;    // per cell: its basin's node (0: drains to a base level)
  std::vector<int32_t> start, cells;  // the pits' cells by node (node u: cells[start[u] .. start[u + 1]))
  std::vector<std::vector<BasinLink>> block_links;  // per block of pits, in scan order
  std::vector<BasinLink> links;
  std::vector<int32_t> parent, owner, slot;  // union-find; per-thread scan slots
  std::vector<int32_t> tree_start, tree;     // the spanning tree's adjacency
  std::vector<int32_t> order;                // nodes from the root outwards
  std::vector<float> level;                  // per node: its water surface
};

// Routes z (left as it is) to the base levels: receivers by steepest descent
// (Rho8 when graph.random is drawn, see draw_rho8), each pit drained over the
// basin graph's spanning tree (file comment), then the stack. `surface`
// receives the water surface: a depression's cells at its spill height (the
// highest pass on its way out), every other cell at its own height. Every
// cell then drains to a base level; a cell under a lake may drain uphill (to
// its pit, then up the carved path to the pass). Deterministic on any thread
// count. `progress` hears the phases.
void route_over_depressions(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph, BasinGraph& basins,
                            float* surface, const Progress& progress = Progress());

}  // namespace ft::erosion
