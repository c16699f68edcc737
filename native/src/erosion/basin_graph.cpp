// SPDX-License-Identifier: GPL-3.0-or-later
// The basin graph's routing over depressions (see basin_graph.hpp).
#include "erosion/basin_graph.hpp"

#include <omp.h>

#include <algorithm>
#include <limits>

#include "core/error.hpp"

namespace ft::erosion {
namespace {

// Blocks of pits scanned in parallel for their passes (a fixed number: the
// links' order, and so the tree's choice among equal passes, never depends
// on the thread count).
constexpr int32_t kLinkBlocks = 64;

int32_t find_root(std::vector<int32_t>& parent, int32_t a) {
  while (parent[a] != a) {
    parent[a] = parent[parent[a]];  // path halving
    a = parent[a];
  }
  return a;
}

// Each cell's basin node: 0 where it drains to a base level, else its pit's
// (pits numbered from 1 in index order), by following receivers to a cell
// already labelled. Then the pits' cells bucketed by node, in index order
// (bg.cells[bg.start[u] .. bg.start[u + 1]) for u >= 1). Returns the number
// of nodes.
int32_t label_basins(const D8Grid& g, int32_t sink, const FlowGraph& graph, BasinGraph& bg) {
  const int32_t n = int32_t(g.size());
  auto& node = bg.node;
  node.assign(size_t(n), -1);
  int32_t nodes = 1;
  for (int32_t i = 0; i < n; ++i)
    if (graph.receiver[i] == i) node[i] = g.is_base(i, sink) ? 0 : nodes++;
  auto& path = bg.order;
  for (int32_t i = 0; i < n; ++i) {
    if (node[i] >= 0) continue;
    path.clear();
    int32_t j = i;
    for (; node[j] < 0; j = graph.receiver[j]) path.push_back(j);
    for (const int32_t p : path) node[p] = node[j];
  }
  bg.start.assign(size_t(nodes) + 1, 0);
  for (int32_t i = 0; i < n; ++i) ++bg.start[node[i] + 1];
  bg.start[1] = 0;  // node 0's cells are not listed
  for (int32_t u = 1; u < nodes; ++u) bg.start[u + 1] += bg.start[u];
  bg.cells.resize(size_t(bg.start[nodes]));
  bg.owner.assign(bg.start.begin(), bg.start.end() - 1);  // cursors
  for (int32_t i = 0; i < n; ++i)
    if (node[i]) bg.cells[bg.owner[node[i]]++] = i;
  return nodes;
}

// The lowest pass between every pair of neighbouring basins of which at
// least one is a pit's, scanned from the pit with the lower node (base
// levels' basins are one node, 0, and never scanned), the lowest by
// BasinLink's order. Blocks of pits are scanned in parallel and
// concatenated in order.
void connect_basins(const D8Grid& g, const float* z, int32_t sink, const FlowGraph& graph, BasinGraph& bg,
                    int32_t nodes) {
  const int threads = omp_get_max_threads();
  bg.owner.assign(size_t(threads) * nodes, -1);
  bg.slot.resize(size_t(threads) * nodes);
  bg.block_links.resize(size_t(kLinkBlocks));
  const float* random = graph.random.empty() ? nullptr : graph.random.data();
  int32_t off[8];
  for (int d = 0; d < 8; ++d) off[d] = kDy[d] * g.width + kDx[d];
  const int32_t sx = g.periodic ? sink % g.width : 0, sy = g.periodic ? sink / g.width : 0;
  auto relative = [&](int32_t i) {
    if (!g.periodic) return uint32_t(i);
    const int32_t x = i % g.width - sx, y = i / g.width - sy;
    return uint32_t((y < 0 ? y + g.height : y) * g.width + (x < 0 ? x + g.width : x));
  };
#pragma omp parallel
  {
    const size_t t = size_t(omp_get_thread_num()) * nodes;
    int32_t* owner = bg.owner.data() + t;  // owner[v] == u: slot[v] holds u's link to v
    int32_t* slot = bg.slot.data() + t;
#pragma omp for schedule(dynamic, 1)
    for (int32_t b = 0; b < kLinkBlocks; ++b) {
      auto& links = bg.block_links[b];
      links.clear();
      auto visit = [&](int32_t i, int32_t u, int32_t j) {
        const int32_t v = bg.node[j];
        if (v == u || (v != 0 && v < u)) return;
        const float h = std::max(z[i], z[j]);
        if (owner[v] == u && h > links[slot[v]].height) return;  // the usual case: decided by height
        // Rho8's number of the pass cell itself (the higher; of equals, the lower number).
        const float tie = !random ? 0.0f
                          : z[i] != z[j] ? random[z[i] > z[j] ? i : j]
                                         : std::min(random[i], random[j]);
        const uint32_t pi = relative(i), pj = relative(j);
        const BasinLink link{h, tie, std::min(pi, pj), std::max(pi, pj), i, j, u, v};
        if (owner[v] != u) {
          owner[v] = u;
          slot[v] = int32_t(links.size());
          links.push_back(link);
        } else if (link < links[slot[v]]) {
          links[slot[v]] = link;
        }
      };
      const int32_t u0 = 1 + int32_t(int64_t(nodes - 1) * b / kLinkBlocks);
      const int32_t u1 = 1 + int32_t(int64_t(nodes - 1) * (b + 1) / kLinkBlocks);
      for (int32_t u = u0; u < u1; ++u)
        for (int32_t k = bg.start[u]; k < bg.start[u + 1]; ++k) {
          const int32_t i = bg.cells[k];
          if (!g.periodic) {
            // A bounded grid's edge cells are base levels (node 0): every
            // pit's cell is interior, with all eight neighbours at fixed offsets.
            for (int d = 0; d < 8; ++d) visit(i, u, i + off[d]);
          } else {
            for (int d = 0; d < 8; ++d) visit(i, u, int32_t(g.neighbour(i % g.width, i / g.width, d)));
          }
        }
    }
  }
  bg.links.clear();
  for (const auto& part : bg.block_links) bg.links.insert(bg.links.end(), part.begin(), part.end());
}

// Kruskal's minimum spanning tree of the links (lowest pass first; equal
// passes by Rho8's number, so that a flat drains along a random tree, not
// along rows), as adjacency lists; then each node's level from the root
// outwards. Afterwards bg.parent[u] is the index of node u's link towards
// the root (the union-find's array, reused), bg.level[u] its water surface.
void spanning_tree(BasinGraph& bg, int32_t nodes) {
  auto& links = bg.links;
  std::sort(links.begin(), links.end());
  auto& parent = bg.parent;
  parent.resize(size_t(nodes));
  for (int32_t u = 0; u < nodes; ++u) parent[u] = u;
  // Accepted links, counted per node (adjacency in CSR form).
  bg.tree_start.assign(size_t(nodes) + 1, 0);
  std::vector<int32_t>& accepted = bg.slot;  // free after connect_basins
  accepted.clear();
  for (int32_t l = 0; l < int32_t(links.size()) && int32_t(accepted.size()) < nodes - 1; ++l) {
    const int32_t ra = find_root(parent, links[l].a), rb = find_root(parent, links[l].b);
    if (ra == rb) continue;
    parent[ra] = rb;
    accepted.push_back(l);
    ++bg.tree_start[links[l].a + 1], ++bg.tree_start[links[l].b + 1];
  }
  for (int32_t u = 0; u < nodes; ++u) bg.tree_start[u + 1] += bg.tree_start[u];
  bg.tree.resize(size_t(bg.tree_start[nodes]));
  bg.owner.assign(bg.tree_start.begin(), bg.tree_start.end() - 1);  // cursors
  for (const int32_t l : accepted) {
    bg.tree[bg.owner[links[l].a]++] = l;
    bg.tree[bg.owner[links[l].b]++] = l;
  }
  // Breadth first from the root: each node's link towards it and its level.
  bg.level.assign(size_t(nodes), -std::numeric_limits<float>::infinity());
  parent.assign(size_t(nodes), -1);
  bg.order.assign(1, 0);
  for (size_t h = 0; h < bg.order.size(); ++h) {
    const int32_t u = bg.order[h];
    for (int32_t e = bg.tree_start[u]; e < bg.tree_start[u + 1]; ++e) {
      const BasinLink& link = links[bg.tree[e]];
      const int32_t w = link.a == u ? link.b : link.a;
      if (w == 0 || parent[w] >= 0) continue;
      parent[w] = bg.tree[e];
      bg.level[w] = std::max(bg.level[u], link.height);
      bg.order.push_back(w);
    }
  }
}

// Drains node u's pit across its pass: the receivers from the pass cell
// down to the pit are reversed, and the pass cell drains to the cell across.
void carve(const D8Grid& g, FlowGraph& graph, const BasinLink& link, int32_t u) {
  const int32_t inside = link.a == u ? link.cell_a : link.cell_b, outside = link.a == u ? link.cell_b : link.cell_a;
  int32_t dx = std::abs(outside % g.width - inside % g.width), dy = std::abs(outside / g.width - inside / g.width);
  // Neighbours across a periodic edge are width - 1 (or height - 1) apart.
  dx = std::min(dx, g.width - dx), dy = std::min(dy, g.height - dy);
  int32_t previous = outside, current = inside;
  float run = float(dx && dy ? g.spacing * M_SQRT2 : g.spacing);
  for (;;) {
    const int32_t next = graph.receiver[current];
    const float next_run = graph.length[current];
    graph.receiver[current] = previous;
    graph.length[current] = run;
    if (next == current) break;  // the pit
    previous = current, run = next_run, current = next;
  }
}

}  // namespace

void route_over_depressions(const D8Grid& g, const float* z, int32_t sink, FlowGraph& graph, BasinGraph& bg,
                            float* surface, const Progress& progress) {
  const int64_t n = int64_t(g.size());
  route_steepest(g, z, sink, graph);
  progress.report(0.2);
  if (graph.pits == 0) {
    std::copy(z, z + n, surface);
    build_stack(g, graph);
    progress.report(1.0);
    return;
  }
  const int32_t nodes = label_basins(g, sink, graph, bg);
  connect_basins(g, z, sink, graph, bg, nodes);
  progress.report(0.55);
  spanning_tree(bg, nodes);
  for (int32_t u = 1; u < nodes; ++u) {
    // The grid is connected, so the tree reaches every pit.
    if (bg.parent[u] < 0) fail(FT_ERR_INTERNAL, "a pit is not connected to a base level (a bug in the basin graph)");
    carve(g, graph, bg.links[bg.parent[u]], u);
  }
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < n; ++i) surface[i] = std::max(z[i], bg.level[bg.node[i]]);
  progress.report(0.7);
  build_stack(g, graph);
  graph.pits = 0;
  progress.report(1.0);
}

}  // namespace ft::erosion
