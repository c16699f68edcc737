// SPDX-License-Identifier: GPL-3.0-or-later
// Rivers across flat ground (see hydrology.hpp, route_plains).
//
// What a river does on a plain: it keeps going, and it gathers. Water that
// comes off a mountain front onto level ground does not run straight to the
// nearest edge in one channel per gully: the streams meet, and the plain is
// drained by few rivers that wander across it (a piedmont's streams join an
// axial river; an alluvial plain's channels join the trunk). Priority-Flood's
// epsilon steps grade a flat by grid distance from its spill, so steepest
// descent across it ran straight, one parallel streak per gully, and beside
// the map's edge (where the steps are float ulps and ties go east) along it.
//
// Here each flat's cells get their receivers from shortest paths over random
// step costs (the cost factors of erosion/flat_resolution.cpp: a path wanders
// some cells aside), laid river by river, the largest first, each to the
// nearest water already laid: an outlet of the flat or a river crossing it.
// A river so joins the one beside it whenever that is nearer than the way
// out, as on a real plain. The plain's other cells drain to the nearest
// laid water by the same costs (one search).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <queue>
#include <vector>

#include "erosion/flow_graph.hpp"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {
namespace {

// Cost factors: integers uniform in kLeast .. kLeast + 15 (as the maps'
// flats, erosion/flat_resolution.cpp); a cardinal step costs the two cells'
// factors added, a diagonal one that times sqrt 2 (181 / 128).
constexpr int32_t kLeast = 4, kSpread = 16;

// A river leaves the flat by an outlet only when no laid river lies within
// this many cells' cost more than the way out (a mean step costs 2 x 11.5):
// on level ground water gathers before it leaves.
constexpr int32_t kJoinReach = 10;
constexpr int64_t kOutletCost = int64_t(kJoinReach) * (2 * kLeast + kSpread - 1);

struct Plain {
  const erosion::D8Grid& g;
  const Water& w;
  std::vector<uint8_t> flat;     // 1: a cell of a flat (land, no lower neighbour, not a base level)
  std::vector<int32_t> factor;   // step cost factor per cell
  Plain(const erosion::D8Grid& grid, const Water& water) : g(grid), w(water) {}

  // A way out of a flat at level `lv`: a cell beside it of the same level
  // that drains (lower ground beside it, or a base level). Never a lake: a
  // lake at the plain's level spills over the plain, not the other way.
  std::vector<int32_t> region;   // per flat cell: its flat (8-connected), else -1
  std::vector<float> lowest;     // per flat: its lowest graded height
  // A way out of the flat of cell c: a cell beside it of the same level
  // that drains (lower ground beside it, or a base level). Never a lake: a
  // lake at the plain's level spills over the plain, not the other way. And
  // below all of the flat on the graded surface (or a base level): the
  // graded routing from there only falls, so it never comes back onto the
  // flat and the graph stays a forest (on eroded ground a level a float
  // step lower may be graded above the flat beside it).
  bool outlet(int64_t j, int32_t c) const {
    return !flat[size_t(j)] && w.label[size_t(j)] < 0 && w.level[size_t(j)] == w.level[size_t(c)] &&
           (w.base[size_t(j)] || w.graded[size_t(j)] < lowest[size_t(region[size_t(c)])]);
  }
  int32_t step(int32_t a, int64_t b, int k) const {
    const int32_t s = factor[size_t(a)] + factor[size_t(b)];
    return (k & 1) ? s * 181 / 128 : s;
  }
};

using Entry = std::pair<int64_t, int32_t>;  // (cost, cell): ties by index, so the order is fixed
using MinHeap = std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>>;

}  // namespace

int64_t route_plains(const erosion::D8Grid& g, const Water& w, double min_area, erosion::FlowGraph& graph) {
  const size_t n = g.size();
  Plain p(g, w);
  p.flat.assign(n, 0);
  int64_t flats = 0;
  for (size_t i = 0; i < n; ++i) {
    if (w.label[i] != kLand || w.base[i]) continue;
    bool lower = false;
    for (int k = 0; k < 8 && !lower; ++k) {
      const int64_t j = g.neighbour(int32_t(i % size_t(g.width)), int32_t(i / size_t(g.width)), k);
      lower = j >= 0 && w.level[size_t(j)] < w.level[i];
    }
    p.flat[i] = !lower;
    flats += !lower;
  }
  if (flats == 0) return 0;
  p.region.assign(n, -1);
  for (size_t i = 0; i < n; ++i) {
    if (!p.flat[i] || p.region[i] >= 0) continue;
    const int32_t id = int32_t(p.lowest.size());
    float lowest = w.graded[i];
    std::vector<int32_t> todo{int32_t(i)};
    p.region[i] = id;
    while (!todo.empty()) {
      const int32_t c = todo.back();
      todo.pop_back();
      lowest = std::min(lowest, w.graded[size_t(c)]);
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(c % g.width, c / g.width, k);
        if (j < 0 || !p.flat[size_t(j)] || p.region[size_t(j)] >= 0) continue;
        p.region[size_t(j)] = id;
        todo.push_back(int32_t(j));
      }
    }
    p.lowest.push_back(lowest);
  }

  // The water each flat cell gets from off the flat (the graded surface's
  // routing, which off the flats is the final one), with its area.
  erosion::build_stack(g, graph);
  std::vector<double> area;
  erosion::accumulate_area(g, graph, area);
  std::vector<double> inflow(n, 0.0);
  for (size_t j = 0; j < n; ++j) {
    const int32_t r = graph.receiver[j];
    if (r != int32_t(j) && !p.flat[j] && p.flat[size_t(r)]) inflow[size_t(r)] += area[j];
  }
  std::vector<float> u;
  erosion::draw_cell_uniforms(g, -1, 0, Stream::kRiverPlains, u);
  p.factor.resize(n);
  for (size_t i = 0; i < n; ++i) p.factor[i] = kLeast + std::min(kSpread - 1, int32_t(u[i] * float(kSpread)));

  // 1. The rivers, the largest first: each by the cheapest way from where it
  //    comes onto the flat to the nearest laid water (an outlet or a river).
  std::vector<int32_t> sources;
  for (size_t i = 0; i < n; ++i)
    if (p.flat[i] && inflow[i] >= min_area) sources.push_back(int32_t(i));
  std::sort(sources.begin(), sources.end(), [&](int32_t a, int32_t b) {
    return inflow[size_t(a)] != inflow[size_t(b)] ? inflow[size_t(a)] > inflow[size_t(b)] : a < b;
  });
  std::vector<uint8_t> laid(n, 0);  // a flat cell whose receiver is final
  std::vector<int64_t> cost(n, INT64_MAX);
  std::vector<int32_t> from(n, -1), touched;
  for (const int32_t s : sources) {
    if (laid[size_t(s)]) continue;  // on a river laid before: it joins there
    MinHeap heap;
    cost[size_t(s)] = 0;
    touched.assign(1, s);
    heap.push({0, s});
    int32_t hit = -1;
    while (!heap.empty()) {
      const auto [d, c] = heap.top();
      heap.pop();
      if (d != cost[size_t(c)]) continue;
      if (c != s && (!p.flat[size_t(c)] || laid[size_t(c)])) { hit = c; break; }  // reached laid water
      const int32_t cx = c % g.width, cy = c / g.width;
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(cx, cy, k);
        if (j < 0) continue;
        const bool target = (p.flat[size_t(j)] && laid[size_t(j)]) || p.outlet(j, c);
        if (!target && !(p.flat[size_t(j)] && !laid[size_t(j)])) continue;
        const bool laid_water = p.flat[size_t(j)] && laid[size_t(j)];
        const int64_t to = d + p.step(c, j, k) + (target && !laid_water ? kOutletCost : 0);
        if (to < cost[size_t(j)]) {
          if (cost[size_t(j)] == INT64_MAX) touched.push_back(int32_t(j));
          cost[size_t(j)] = to, from[size_t(j)] = c;
          heap.push({to, int32_t(j)});
        }
      }
    }
    if (hit >= 0)
      for (int32_t c = hit; c != s;) {  // the path, downstream to upstream
        const int32_t up = from[size_t(c)];
        graph.receiver[size_t(up)] = c;
        laid[size_t(up)] = 1;
        c = up;
      }
    for (const int32_t t : touched) cost[size_t(t)] = INT64_MAX, from[size_t(t)] = -1;
  }

  // 2. The rest of each flat drains to the nearest laid water by the same
  //    costs: one search from every cell beside it.
  MinHeap heap;
  for (size_t i = 0; i < n; ++i) {
    if (!p.flat[i] || laid[i]) continue;
    const int32_t cx = int32_t(i % size_t(g.width)), cy = int32_t(i / size_t(g.width));
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(cx, cy, k);
      if (j < 0 || !((p.flat[size_t(j)] && laid[size_t(j)]) || p.outlet(j, int32_t(i)))) continue;
      const int64_t to = p.step(int32_t(i), j, k);
      if (to < cost[i]) cost[i] = to, from[i] = int32_t(j);
    }
    if (from[i] >= 0) heap.push({cost[i], int32_t(i)});
  }
  int64_t rerouted = 0;
  while (!heap.empty()) {
    const auto [d, c] = heap.top();
    heap.pop();
    if (d != cost[size_t(c)] || laid[size_t(c)]) continue;
    laid[size_t(c)] = 1;
    graph.receiver[size_t(c)] = from[size_t(c)];
    const int32_t cx = c % g.width, cy = c / g.width;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(cx, cy, k);
      if (j < 0 || !p.flat[size_t(j)] || laid[size_t(j)]) continue;
      const int64_t to = d + p.step(c, j, k);
      if (to < cost[size_t(j)]) cost[size_t(j)] = to, from[size_t(j)] = c, heap.push({to, int32_t(j)});
    }
  }
  // Lengths of the new steps; a flat no laid water reaches (one whose way
  // out passes a lake at its level) keeps the graded surface's receivers.
  for (size_t i = 0; i < n; ++i) {
    if (!p.flat[i] || !laid[i]) continue;
    ++rerouted;
    const int32_t r = graph.receiver[i];
    const int32_t dx = std::abs(r % g.width - int32_t(i % size_t(g.width)));
    const int32_t dy = std::abs(r / g.width - int32_t(i / size_t(g.width)));
    graph.length[i] = float((dx != 0 && dy != 0) ? g.spacing * M_SQRT2 : g.spacing);
  }
  return rerouted;
}

}  // namespace ft::hydrology
