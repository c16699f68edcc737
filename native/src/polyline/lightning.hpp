// SPDX-License-Identifier: GPL-3.0-or-later
// Branching lightning on the FPL engine: a main FPL through the base nodes,
// whose midpoints fork side branches: a split of recursion level l forks with
// probability branch_prob * 2^(-l/2), so the expected number of forks grows
// only as 2^(l/2) per level while their length halves (a few long branches,
// more short ones, as in real discharges, instead of a fuzz of tiny ones). A branch
// forked at the split of segment a -> b (level l) starts at the midpoint d,
// leaves the direction d -> b at 20..45 degrees to a random side (in the x,y
// plane, in the FPL3D plane, or about a random perpendicular axis in 3D),
// is branch_decay * |b - a| long and is itself an FPL of depth r - l - 1, so
// its finest segments match the main line's. Generation g has radius
// radius * decay^g and forks again until branch_generations. Every line
// tapers linearly to decay x its start radius.
//
// All draws are keyed by position: the fork decision and angles of split
// (l, j) of a line use Counter{line, l, kPolylineBranch}, indices 4j..4j+3;
// a branch's own FPL uses the key mix(parent key, line, l, j). Branches are
// listed in the order (generation, parent, level, node), the same whether
// the tree came from the breadth-first or the depth-first path.
#pragma once

#include "core/polyline_set.hpp"
#include "polyline/fpl.hpp"

namespace ft::polyline {

struct BranchConfig {
  double prob = 0.0;
  double decay = 0.5;
  int generations = 3;
  double radius = 0.01;
};

// The main line through `base` followed by its branches (prob may be 0).
PolylineSet fpl_lightning(const FplConfig& c, const std::vector<Vec3>& base, const BranchConfig& b);

}  // namespace ft::polyline
