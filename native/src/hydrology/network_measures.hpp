// SPDX-License-Identifier: GPL-3.0-or-later
// Measures of a river network for `fracterra analyze` and `rivers --stats`:
// Horton's ratios (analysis/horton), total length, drainage density and
// Hack's h.
#pragma once

#include "analysis/horton.hpp"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {

struct NetworkMeasures {
  analysis::HortonRatios horton;            // orders and streams; ratios 0 when fewer than two orders
  bool has_horton = false;
  double total_length = 0;        // world units
  double land_area = 0;           // world units^2: cells neither sea nor lake
  double drainage_density = 0;    // total length / land area (1 / world units)
  double hack_h = 0, hack_h_stderr = 0;  // L ~ A^h: longest upstream length against area, per segment mouth
  int32_t hack_points = 0;
  int64_t segments = 0, lakes = 0, vertices = 0;
  int32_t ends[5] = {};           // segments ending at a confluence, the sea, a lake, the edge, a sink
};

NetworkMeasures measure_network(const RiverNetwork& net);

}  // namespace ft::hydrology
