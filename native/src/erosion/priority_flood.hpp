// SPDX-License-Identifier: GPL-3.0-or-later
// The Priority-Flood driver (Barnes, Lehman & Mulla 2014, "Priority-Flood: an
// optimal depression-filling and watershed-labeling algorithm", Alg. 1 and
// 3) shared by fill_depressions (priority_flood.cpp) and hydrology's
// fill_lakes: cells are taken out from the outlets upwards, lowest first (a
// radix heap), except cells raised onto a flat, which go through a FIFO and
// are taken out before any heap cell (Algorithm 3's pit queue: no heap cost
// inside depressions). What a visit does to a cell is the caller's step.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/radix_heap.hpp"

namespace ft::erosion {

// The outlets of a bounded grid, in the order the floods seed them (which
// fixes the order of equal heights): the top and bottom rows column by
// column, then the left and right columns row by row (corners twice).
inline std::vector<int32_t> edge_cells(const D8Grid& g) {
  std::vector<int32_t> cells;
  cells.reserve(2 * (size_t(g.width) + size_t(g.height)));
  for (int32_t x = 0; x < g.width; ++x)
    cells.push_back(x), cells.push_back(int32_t(size_t(g.height - 1) * g.width + x));
  for (int32_t y = 0; y < g.height; ++y)
    cells.push_back(int32_t(size_t(y) * g.width)), cells.push_back(int32_t(size_t(y) * g.width + g.width - 1));
  return cells;
}

// Every base level, in seeding order: the edge (bounded) or `sink`
// (periodic), then the sea's cells in index order.
inline std::vector<int32_t> outlet_cells(const D8Grid& g, int32_t sink) {
  std::vector<int32_t> cells = g.periodic ? std::vector<int32_t>{sink} : edge_cells(g);
  if (g.sea)
    for (size_t i = 0; i < g.size(); ++i)
      if (g.sea[i]) cells.push_back(int32_t(i));
  return cells;
}

// Floods the grid from `seeds` (a cell listed twice counts once), keyed by
// `key` (the seeds' keys are read as they are seeded). Every other reachable
// cell j is reached once, from the neighbour c taken out first:
// step(c, j) updates j and returns true to queue it in the FIFO (a cell
// raised just above c) or false to queue it in the heap at key[j], read
// after the step. Keys taken out never decrease (the radix heap's rule): a
// step may only raise key[j] to at least key[c]. `closed`: empty, or one
// flag per cell, non-zero for cells the flood must not visit (the seeds'
// flags 0); the flood flags what it takes. `progress` hears the share of
// the cells to take that are taken, every 64th of the grid (2^12 cells at
// least: a 4097^2 grid's flood takes seconds, so the bar moves and a
// cancel is seen inside it; every 2^20 cells, its steps were 6% of it).
template <class Step>
void priority_flood(const D8Grid& g, const std::vector<int32_t>& seeds, const float* key, Step&& step,
                    const Progress& progress = Progress(), std::vector<uint8_t> closed = {}) {
  const size_t every = std::max<size_t>(g.size() / 64, size_t(1) << 12);
  size_t taken = 0, next_report = every, cells = g.size();
  if (closed.empty()) closed.assign(g.size(), 0);
  else cells = size_t(std::count(closed.begin(), closed.end(), uint8_t(0)));
  RadixHeap open;
  std::vector<int32_t> fifo;  // taken from `head`; emptied when all are taken
  size_t head = 0;
  for (const int32_t s : seeds)
    if (!closed[s]) {
      closed[s] = 1;
      open.push(key[s], s);
    }
  while (!open.empty() || head < fifo.size()) {
    int32_t c;
    if (head < fifo.size()) {
      c = fifo[head++];
      if (head == fifo.size()) fifo.clear(), head = 0;
    } else {
      c = open.pop();
    }
    if (++taken == next_report) {
      progress.report(double(taken) / double(cells));
      next_report += every;
    }
    const int32_t cx = c % g.width, cy = c / g.width;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(cx, cy, k);
      if (j < 0 || closed[j]) continue;
      closed[j] = 1;
      if (step(c, int32_t(j))) fifo.push_back(int32_t(j));
      else open.push(key[j], int32_t(j));
    }
  }
}

}  // namespace ft::erosion
