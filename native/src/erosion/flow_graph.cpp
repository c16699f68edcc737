// D8 receivers, the stack and drainage area (see flow_graph.hpp).
#include "erosion/flow_graph.hpp"

#include <algorithm>

namespace ft::erosion {

int32_t periodic_sink(const D8Grid& g, const float* z) {
  const size_t n = g.size();
  size_t best = 0;
  for (size_t i = 1; i < n; ++i)
    if (z[i] < z[best]) best = i;
  return int32_t(best);
}

void route_steepest(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph) {
  const size_t n = g.size();
  graph.receiver.resize(n);
  graph.length.resize(n);
  const float inv_diag = float(1.0 / M_SQRT2);
  const float straight = float(g.spacing), diag = float(g.spacing * M_SQRT2);
  int64_t pits = 0;
#pragma omp parallel for schedule(static) reduction(+ : pits)
  for (int32_t y = 0; y < g.height; ++y) {
    for (int32_t x = 0; x < g.width; ++x) {
      const size_t i = size_t(y) * g.width + x;
      int32_t best = int32_t(i);
      int best_k = -1;
      float best_slope = 0.0f;  // drop per unit of spacing
      const bool base = g.periodic ? int32_t(i) == sink : g.on_edge(x, y);
      if (!base) {
        const bool interior = x > 0 && y > 0 && x < g.width - 1 && y < g.height - 1;
        for (int k = 0; k < 8; ++k) {
          const int64_t j = interior ? int64_t(i) + kDy[k] * int64_t(g.width) + kDx[k] : g.neighbour(x, y, k);
          const float drop = (z[i] - z[j]) * ((k & 1) ? inv_diag : 1.0f);
          if (drop > best_slope) {
            best_slope = drop;
            best = int32_t(j);
            best_k = k;
          }
        }
        if (best == int32_t(i)) ++pits;
      }
      graph.receiver[i] = best;
      graph.length[i] = best_k < 0 ? 0.0f : ((best_k & 1) ? diag : straight);
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
  graph.stack.resize(size_t(n));
  auto& todo = graph.work;  // now the DFS stack: at most n entries
  int32_t pos = 0;
  for (int32_t b = 0; b < n; ++b) {
    if (graph.receiver[b] != b) continue;
    size_t top = 0;
    todo[top++] = b;
    while (top > 0) {
      const int32_t c = todo[--top];
      graph.stack[pos++] = c;
      for (int32_t k = start[c]; k < start[c + 1]; ++k) todo[top++] = graph.donors[k];
    }
  }
}

void accumulate_area(const D8Grid& g, const FlowGraph& graph, std::vector<double>& area) {
  const size_t n = g.size();
  area.assign(n, g.spacing * g.spacing);
  for (size_t k = n; k-- > 0;) {
    const int32_t i = graph.stack[k];
    const int32_t r = graph.receiver[i];
    if (r != i) area[r] += area[i];
  }
}

void route_filled(const D8Grid& g, float* z, int32_t sink, FlowGraph& graph) {
  route_steepest(g, z, sink, graph);
  // Local fills can spill into a neighbouring pit that a later fill raises;
  // another round handles that. A fractal terrain's first step has pits
  // everywhere (more than one in 256 cells): one global fill is cheaper then;
  // later steps have about one in 1000 (diffusion on banks).
  for (int round = 0; graph.pits > 0; ++round) {
    if (round >= 4 || graph.pits * 256 > int64_t(g.size())) fill_depressions(g, z, sink);
    else fill_pits_locally(g, z, sink, graph);
    route_steepest(g, z, sink, graph);
  }
  build_stack(g, graph);
}

}  // namespace ft::erosion
