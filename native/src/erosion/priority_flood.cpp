// SPDX-License-Identifier: GPL-3.0-or-later
// Priority-Flood+epsilon (Barnes, Lehman & Mulla 2014, "Priority-Flood: an
// optimal depression-filling and watershed-labeling algorithm", Alg. 3):
// cells are visited from the outlets upwards in order of height; a cell not
// above the one it was reached from is raised one float step above it and
// goes through a FIFO (no heap cost inside depressions). With random numbers
// (Rho8's, see flow_graph.hpp) a raised cell is 1 to 4 float steps above
// and goes through the heap instead: a flat is graded by a random passage
// time from its spill, not by Chebyshev distance, so its drainage wanders
// instead of running along rows and diagonals.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <vector>

#include "erosion/flow_graph.hpp"
#include "erosion/priority_flood.hpp"
#include "erosion/radix_heap.hpp"

namespace ft::erosion {
namespace {

struct Open {
  float z;
  int32_t i;
  // Lowest first; equal heights by index so the order is fixed.
  bool operator<(const Open& o) const { return z > o.z || (z == o.z && i > o.i); }
};

// A binary heap on a vector that keeps its storage between searches
// (std::priority_queue can only be emptied by popping or reallocating).
struct OpenHeap {
  std::vector<Open> v;
  bool empty() const { return v.empty(); }
  void clear() { v.clear(); }
  void push(Open o) {
    v.push_back(o);
    std::push_heap(v.begin(), v.end());
  }
  int32_t pop() {
    std::pop_heap(v.begin(), v.end());
    const int32_t i = v.back().i;
    v.pop_back();
    return i;
  }
};

// 1 float step above z, or 1 to 4 by the cell's random number.
inline float raised(float z, const float* random, int32_t j) {
  float up = std::nextafter(z, INFINITY);
  if (random)
    for (int k = int(random[j] * 4.0f); k > 0; --k) up = std::nextafter(up, INFINITY);
  return up;
}

}  // namespace

int64_t fill_depressions(const D8Grid& g, float* z, int32_t sink, const float* random, const Progress& progress) {
  int64_t raised_cells = 0;
  priority_flood(
      g, outlet_cells(g, sink), z,
      [&](int32_t c, int32_t j) {
        if (z[j] > z[c]) return false;
        z[j] = raised(z[c], random, j);
        ++raised_cells;
        return !random;  // graded by random steps: through the heap
      },
      progress);
  return raised_cells;
}

int64_t fill_closed_basins(const D8Grid& g, float* z, int32_t sink, const Progress& progress, bool flat) {
  // 1. The cells that drain as they are: breadth first from the base levels
  //    up every strictly rising step (`flat`: every step that does not
  //    fall, as such a path is never raised). A drained cell with a neighbour not
  //    (yet) reached that is not above it is a seed of the flood: every cell
  //    the flood must visit borders one (a neighbour above a drained cell is
  //    reached from it), and a seed whose neighbours all drain in the end is
  //    taken out with nothing left to do.
  const size_t n = g.size();
  std::vector<uint8_t> closed(n, 0);
  std::vector<int32_t> queue, seeds;
  queue.reserve(n);
  for (const int32_t o : outlet_cells(g, sink))
    if (!closed[o]) {
      closed[o] = 1;
      queue.push_back(o);
    }
  // The bar, in the time of a flooded cell: a drained one costs a fifth of
  // it (4097^2: 0.45 s of CPU for 9.4 M drained cells, 1.8 s for the flood
  // of the other 7.3 M). While the pass runs, the cells it has not reached
  // are counted as flooded: the share done only rises, and ends where the
  // flood's part starts.
  constexpr double kDrainedCost = 0.2;
  auto drained_share = [&](size_t drained) {
    return kDrainedCost * double(drained) / (kDrainedCost * double(drained) + double(n - drained));
  };
  const size_t every = std::max<size_t>(n / 64, size_t(1) << 12);
  for (size_t head = 0, next_report = every; head < queue.size(); ++head) {
    if (head == next_report) {
      progress.report(drained_share(head));
      next_report += every;
    }
    const int32_t c = queue[head];
    const int32_t cx = c % g.width, cy = c / g.width;
    bool seed = false;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(cx, cy, k);
      if (j < 0 || closed[j]) continue;
      if (z[j] > z[c] || (flat && z[j] == z[c])) {
        closed[j] = 1;
        queue.push_back(int32_t(j));
      } else {
        seed = true;
      }
    }
    if (seed) seeds.push_back(c);
  }
  const double flood_start = drained_share(queue.size());
  progress.report(flood_start);
  std::vector<int32_t>().swap(queue);
  // 2. Priority-Flood+epsilon from the seeds over the rest: what
  //    fill_depressions does there (it never raises a drained cell), with
  //    the drained cells' heap traffic saved. Flat: Priority-Flood without
  //    the epsilon (Barnes et al. 2014, Algorithm 2 with the pit queue).
  for (const int32_t s : seeds) closed[s] = 0;
  int64_t raised_cells = 0;
  const ProgressPart flood(progress, flood_start, 1.0 - flood_start);
  priority_flood(
      g, seeds, z,
      [&](int32_t c, int32_t j) {
        if (z[j] > z[c]) return false;
        if (flat) {
          raised_cells += z[j] < z[c];
          z[j] = z[c];
        } else {
          z[j] = raised(z[c], nullptr, j);
          ++raised_cells;
        }
        return true;
      },
      flood.progress(), std::move(closed));
  return raised_cells;
}

void fill_pits_locally(const D8Grid& g, float* z, int32_t sink, FlowGraph& graph) {
  const size_t n = g.size();
  if (graph.seen.size() != n) {
    graph.seen.assign(n, 0);
    graph.closed.assign(n, 0);
    graph.stamp = 0;
  }
  auto is_outlet = [&](int32_t c) { return g.is_base(c, sink); };
  std::vector<int32_t> pits;
  for (size_t i = 0; i < n; ++i)
    if (graph.receiver[i] == int32_t(i) && !is_outlet(int32_t(i))) pits.push_back(int32_t(i));
  OpenHeap open;
  // Step 2 visits heights upwards from the spill: a radix heap (raised cells
  // go through it too when graded by random steps).
  RadixHeap flood;
  std::deque<int32_t> pit_queue;
  graph.changed.clear();
  for (const int32_t p : pits) {
    // An earlier fill may have drained this pit already (same depression).
    bool drained = false;
    for (int k = 0; k < 8 && !drained; ++k) {
      const int64_t j = g.neighbour(p % g.width, p / g.width, k);
      drained = j >= 0 && z[j] < z[p];
    }
    if (drained) continue;
    // Two stamps per pit: stamp - 1 marks "in this region, not closed yet".
    if (graph.stamp >= UINT32_MAX - 2) {  // about to wrap: start afresh
      std::fill(graph.seen.begin(), graph.seen.end(), 0);
      std::fill(graph.closed.begin(), graph.closed.end(), 0);
      graph.stamp = 0;
    }
    graph.stamp += 2;
    const uint32_t stamp = graph.stamp;
    // 1. Flood from the pit, lowest first, to the first cell that drains out.
    graph.region.clear();
    open.clear();
    open.push({z[p], p});
    graph.seen[p] = stamp;
    int32_t spill = -1;
    while (!open.empty()) {
      const int32_t c = open.pop();
      const int32_t cx = c % g.width, cy = c / g.width;
      bool drains = is_outlet(c);
      for (int k = 0; k < 8 && !drains; ++k) {
        const int64_t j = g.neighbour(cx, cy, k);
        drains = j >= 0 && graph.seen[j] != stamp && z[j] < z[c];
      }
      if (drains) {
        spill = c;
        break;
      }
      graph.region.push_back(c);
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(cx, cy, k);
        if (j < 0 || graph.seen[j] == stamp) continue;
        graph.seen[j] = stamp;
        open.push({z[j], int32_t(j)});
      }
    }
    // 2. Priority-Flood+epsilon from the spill cell over the depression only
    //    (and the cells of a flat at the spill level next to it).
    const float spill_level = z[spill];
    flood.restart();
    flood.push(z[spill], spill);
    graph.closed[spill] = stamp;
    for (const int32_t c : graph.region) graph.closed[c] = stamp - 1;  // in the region, not yet closed
    const float* random = graph.random.empty() ? nullptr : graph.random.data();
    while (!flood.empty() || !pit_queue.empty()) {
      int32_t c;
      if (!pit_queue.empty()) {
        c = pit_queue.front();
        pit_queue.pop_front();
      } else {
        c = flood.pop();
      }
      const int32_t cx = c % g.width, cy = c / g.width;
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(cx, cy, k);
        if (j < 0 || graph.closed[j] == stamp) continue;
        // Beyond the depression, only cells on a flat at the spill level
        // that the raised cells would otherwise cut off (ties).
        const bool in_region = graph.closed[j] == stamp - 1 && graph.seen[j] == stamp;
        if (!in_region && (is_outlet(int32_t(j)) || z[j] < spill_level || z[j] > z[c])) continue;
        graph.closed[j] = stamp;
        if (z[j] <= z[c]) {
          z[j] = raised(z[c], random, int32_t(j));
          if (random) flood.push(z[j], int32_t(j));
          else pit_queue.push_back(int32_t(j));
          graph.changed.push_back(int32_t(j));
        } else {
          flood.push(z[j], int32_t(j));
        }
      }
    }
  }
}

}  // namespace ft::erosion
