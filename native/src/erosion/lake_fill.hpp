// SPDX-License-Identifier: GPL-3.0-or-later
// Sediment settling in a lake. Still water spreads what its rivers bring
// over the whole lake, so the lake fills as a flat floor from its lowest
// cell up to its surface. Laid along the flow path instead (each lake cell
// filling to the surface before passing the rest on), the carved path from
// a pit to its pass filled first and stood as a straight one-cell wall
// across the hollow (issue 24: a maze of walls 3-6 cm high in the filled
// hollow of the default mountain).
#pragma once

#include <cstdint>
#include <vector>

#include "erosion/flow_graph.hpp"

namespace ft::erosion {

// The lakes of one routing: a cell is under a lake when its water surface
// (route_over_depressions' `surface`) stands above its height, and a lake is
// the cells under one surface that drain to one another; all of them drain
// out through its exit, the one whose receiver is not in the lake.
class LakeFill {
 public:
  // `z` is read and raised; `surface` and `bed` (the heights the surface
  // was found for) are the routing's. `cell`: a cell's area.
  LakeFill(const FlowGraph& graph, const float* surface, const float* bed, float* z, double cell)
      : graph_(graph), surface_(surface), bed_(bed), z_(z), cell_(cell) {}

  bool under(int32_t i) const { return surface_[i] > bed_[i]; }
  // Whether j is under the lake that i is under (one surface).
  bool in_lake_of(int32_t j, int32_t i) const { return under(j) && surface_[j] == surface_[i]; }

  // Lays up to `load` (volume) in the lake whose exit is `exit`, as a flat
  // floor from the bottom up, never above the surface; returns the volume
  // laid (the rest spills on). Visits the lake's cells through the donor
  // lists: its cost is the lake's size.
  double fill(int32_t exit, double load);

 private:
  const FlowGraph& graph_;
  const float* surface_;
  const float* bed_;
  float* z_;
  double cell_;
  std::vector<int32_t> cells_, todo_;  // scratch, kept between lakes
};

}  // namespace ft::erosion
