// SPDX-License-Identifier: GPL-3.0-or-later
// D8 (or Rho8) receivers, the stack and drainage area (see flow_graph.hpp).
#include "erosion/flow_graph.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace ft::erosion {

int32_t periodic_sink(const D8Grid& g, const float* z) {
  const size_t n = g.size();
  size_t best = 0;
  for (size_t i = 1; i < n; ++i)
    if (z[i] < z[best]) best = i;
  return int32_t(best);
}

namespace {


// Steepest descent on cells x0 .. x1 - 1 of an interior row (all eight
// neighbours at the offsets `off`): selects instead of branches, restrict
// parameters of a function that is not inlined. (GCC 12 keeps the loop
// scalar, maxss and cmov, without -march: no vector blend of an int by a
// float compare in SSE2.) Ties go to the first direction (strict >), as in the general path. A
// diagonal drop is over a run of sqrt 2 (D8) or 2 - r (Rho8, r = `random`,
// indexed like z).
template <bool kRho8>
[[gnu::noinline]] int64_t steepest_interior(const float* __restrict z, const float* __restrict random,
                                            int32_t* __restrict receiver, float* __restrict length, int64_t row,
                                            int32_t x0, int32_t x1, const int32_t* off, float straight, float diag) {
  const int32_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  // Index 8: no lower neighbour (a pit: its own receiver, run 0).
  const int32_t o9[9] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7], 0};
  const float run[9] = {straight, diag, straight, diag, straight, diag, straight, diag, 0.0f};
  const float inv_diag = float(1.0 / M_SQRT2);
  int64_t pits = 0;
  for (int32_t x = x0; x < x1; ++x) {
    const int32_t i = int32_t(row + x);
    const float w = kRho8 ? rho8_diagonal_weight(random[i]) : inv_diag;
    // Only the slope and the direction are selected in the loop (the
    // offset and run from tables after it): one float and one integer
    // select per direction, which GCC makes branch-free; three selects
    // became branches, mispredicted about half the time under Rho8's
    // random choices.
    float best_slope = 0.0f;
    int32_t best_k = 8;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      const float drop = (z[i] - z[i + o[k]]) * ((k & 1) ? w : 1.0f);
      const bool steeper = drop > best_slope;
      best_slope = std::max(drop, best_slope);
      best_k = steeper ? k : best_k;
    }
    receiver[i] = i + o9[best_k];
    length[i] = run[best_k];
    pits += best_k == 8;
  }
  return pits;
}

// The general path: cell (x, y) of any row; returns 1 for a new pit.
int route_cell(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph, int32_t x, int32_t y) {
  const size_t i = size_t(y) * g.width + x;
  const float w = graph.random.empty() ? float(1.0 / M_SQRT2) : rho8_diagonal_weight(graph.random[i]);
  int32_t best = int32_t(i);
  int best_k = -1;
  float best_slope = 0.0f;  // drop per unit of spacing
  const bool base = g.is_base(int32_t(i), x, y, sink);
  if (!base) {
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(x, y, k);
      const float drop = (z[i] - z[j]) * ((k & 1) ? w : 1.0f);
      if (drop > best_slope) {
        best_slope = drop;
        best = int32_t(j);
        best_k = k;
      }
    }
  }
  graph.receiver[i] = best;
  graph.length[i] = best_k < 0 ? 0.0f : float((best_k & 1) ? g.spacing * M_SQRT2 : g.spacing);
  return !base && best_k < 0;
}

}  // namespace

void route_steepest(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph) {
  const size_t n = g.size();
  graph.receiver.resize(n);
  graph.length.resize(n);
  const float straight = float(g.spacing), diag = float(g.spacing * M_SQRT2);
  int32_t off[8];
  for (int k = 0; k < 8; ++k) off[k] = kDy[k] * g.width + kDx[k];
  int64_t pits = 0;
#pragma omp parallel for schedule(static) reduction(+ : pits)
  for (int32_t y = 0; y < g.height; ++y) {
    if (y == 0 || y == g.height - 1) {
      for (int32_t x = 0; x < g.width; ++x) pits += route_cell(g, z, sink, graph, x, y);
      continue;
    }
    pits += route_cell(g, z, sink, graph, 0, y);
    pits += route_cell(g, z, sink, graph, g.width - 1, y);
    const int64_t row = int64_t(y) * g.width;
    pits += graph.random.empty()
                ? steepest_interior<false>(z, nullptr, graph.receiver.data(), graph.length.data(), row, 1,
                                           g.width - 1, off, straight, diag)
                : steepest_interior<true>(z, graph.random.data(), graph.receiver.data(),
                                          graph.length.data(), row, 1, g.width - 1, off, straight, diag);
    // A periodic grid's sink and the sea are base levels wherever they are:
    // the interior path routed them like any cell (and counted them if they
    // had no lower neighbour).
    if (g.periodic && sink / g.width == y) {
      pits -= graph.receiver[sink] == sink;
      pits += route_cell(g, z, sink, graph, sink % g.width, y);
    }
    if (g.sea)
      for (int32_t x = 1; x < g.width - 1; ++x)
        if (g.sea[row + x] && int64_t(sink) != row + x) {
          pits -= graph.receiver[row + x] == int32_t(row + x);
          route_cell(g, z, sink, graph, x, y);
        }
  }
  graph.pits = pits;
}

void build_stack(const D8Grid& g, FlowGraph& graph) {
  const int32_t n = int32_t(g.size());
  auto& start = graph.donor_start;
  start.assign(size_t(n) + 1, 0);
  for (int32_t i = 0; i < n; ++i)
    if (graph.receiver[i] != i) ++start[graph.receiver[i] + 1];
  for (int32_t i = 0; i < n; ++i) start[i + 1] += start[i];
  graph.donors.resize(size_t(start[n]));
  // Fill by a running cursor per receiver (reusing `work` as the cursor).
  graph.work.assign(start.begin(), start.end() - 1);
  for (int32_t i = 0; i < n; ++i) {
    const int32_t r = graph.receiver[i];
    if (r != i) graph.donors[graph.work[r]++] = i;
  }
  // The base levels in index order, cut into kStackChunks runs of about
  // equal count. Each run's trees are searched depth-first into the run's
  // own part of `work`, at an offset known only afterwards, so the runs go
  // to threads and are then copied into place: the stack is the same as a
  // serial search's on any thread count.
  graph.bases.clear();
  for (int32_t b = 0; b < n; ++b)
    if (graph.receiver[b] == b) graph.bases.push_back(b);
  const int32_t nb = int32_t(graph.bases.size());
  const int32_t chunks = std::min<int32_t>(kStackChunks, nb);
  graph.chunk_start.assign(size_t(chunks) + 1, 0);
  auto& parts = graph.parts;
  parts.resize(size_t(chunks));
  graph.todo.resize(size_t(chunks));
#pragma omp parallel for schedule(dynamic, 1)
  for (int32_t c = 0; c < chunks; ++c) {
    auto& part = parts[c];
    auto& todo = graph.todo[c];
    part.clear();
    todo.clear();
    for (int32_t q = int32_t(int64_t(nb) * c / chunks); q < int32_t(int64_t(nb) * (c + 1) / chunks); ++q) {
      todo.push_back(graph.bases[q]);
      while (!todo.empty()) {
        const int32_t v = todo.back();
        todo.pop_back();
        part.push_back(v);
        for (int32_t k = start[v]; k < start[v + 1]; ++k) todo.push_back(graph.donors[k]);
      }
    }
  }
  for (int32_t c = 0; c < chunks; ++c) graph.chunk_start[c + 1] = graph.chunk_start[c] + int32_t(parts[c].size());
  graph.stack.resize(size_t(n));
#pragma omp parallel for schedule(static)
  for (int32_t c = 0; c < chunks; ++c)
    std::copy(parts[c].begin(), parts[c].end(), graph.stack.begin() + graph.chunk_start[c]);
}

void accumulate_area(const D8Grid& g, const FlowGraph& graph, std::vector<double>& area) {
  area.assign(g.size(), g.spacing * g.spacing);
  const int32_t chunks = int32_t(graph.chunk_start.size()) - 1;
  // Each chunk holds whole trees: chunks are independent, each summed in
  // stack order.
#pragma omp parallel for schedule(dynamic, 1)
  for (int32_t c = 0; c < chunks; ++c)
    for (int32_t k = graph.chunk_start[c + 1]; k-- > graph.chunk_start[c];) {
      const int32_t i = graph.stack[k];
      const int32_t r = graph.receiver[i];
      if (r != i) area[r] += area[i];
    }
}

void reroute_changed(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph) {
  int64_t pits = graph.pits;
  for (const int32_t c : graph.changed) {
    const int32_t cx = c % g.width, cy = c / g.width;
    for (int k = -1; k < 8; ++k) {
      const int64_t j = k < 0 ? c : g.neighbour(cx, cy, k);
      if (j < 0) continue;
      const int32_t x = int32_t(j % g.width), y = int32_t(j / g.width);
      // A cell may be routed more than once (neighbour of several raised
      // cells): count its pit only by the change.
      pits -= graph.receiver[j] == j && !g.is_base(int32_t(j), x, y, sink);
      pits += route_cell(g, z, sink, graph, x, y);
    }
  }
  graph.pits = pits;
}

void route_and_fill(const D8Grid& g, float* z, int32_t sink, FlowGraph& graph, const Progress& progress) {
  // Shares of the bar (a 4097^2 step routes for seconds): the routing, then
  // each round of fills a part of what is left, a global fill all of it.
  constexpr double kRouted = 0.3;
  double done = kRouted;
  route_steepest(g, z, sink, graph);
  progress.report(done);
  // Local fills can spill into a neighbouring pit that a later fill raises;
  // another round handles that. A fractal terrain's first step has pits
  // everywhere: one global fill is cheaper when more than one cell in 16 is
  // a pit; later steps have about one in 1000 (diffusion on banks), mostly
  // one or two cells deep.
  for (int round = 0; graph.pits > 0; ++round) {
    if (round >= 4 || graph.pits * 16 > int64_t(g.size())) {
      const ProgressPart fill(progress, done, 1.0 - done);
      fill_depressions(g, z, sink, graph.random.empty() ? nullptr : graph.random.data(), fill.progress());
      route_steepest(g, z, sink, graph);
      // A global fill leaves every cell a strictly lower neighbour: a pit
      // after it is a bug (or a height that is not finite), and looping
      // would hang the caller instead of reporting it.
      if (graph.pits > 0)
        fail(FT_ERR_INTERNAL, std::to_string(graph.pits) + " cells have no lower neighbour after filling "
                              "their depressions (a bug in the flow routing)");
    } else {
      fill_pits_locally(g, z, sink, graph);
      // Routing a cell and its neighbours one by one costs about 30 times
      // a cell of the vectorised full routing.
      if (graph.changed.size() * 32 < g.size()) reroute_changed(g, z, sink, graph);
      else route_steepest(g, z, sink, graph);
      done += 0.5 * (1.0 - done);
      progress.report(done);
    }
  }
}

void route_filled(const D8Grid& g, float* z, int32_t sink, FlowGraph& graph, const Progress& progress) {
  {
    const ProgressPart filling(progress, 0.0, 0.8);
    route_and_fill(g, z, sink, graph, filling.progress());
  }
  progress.report(0.8);
  build_stack(g, graph);
  progress.report(1.0);
}

}  // namespace ft::erosion
