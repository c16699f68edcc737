// Fluvial erosion by the stream-power law dz/dt = U - K A^m S, solved
// implicitly along the stack (Braun & Willett 2013, eq. 8 with n = 1):
//   z_i' = (z_i + F z_r') / (1 + F),  F = K dt A_i^m / L_i,
// where r is i's receiver, already updated because the stack lists it
// first. Unconditionally stable, so a few large steps carve a valley
// network. Depressions are filled before routing (Priority-Flood+epsilon);
// the implicit solve keeps z_i' > z_r' whenever z_i > z_r, so new pits come
// only from diffusion and are rare: the fill (the one O(n log n) part) runs
// only on steps that have them.
#include <cmath>
#include <vector>

#include "erosion/erosion.hpp"
#include "erosion/flow_graph.hpp"

namespace ft::erosion {

void fluvial(const D8Grid& g, float* z, const FluvialConfig& c, const Progress& progress) {
  const size_t n = g.size();
  FlowGraph graph;
  std::vector<double> area;
  std::vector<float> erodibility(n);  // K dt A^m, per cell
  const int32_t sink = g.periodic ? periodic_sink(g, z) : -1;
  for (int32_t step = 0; step < c.steps; ++step) {
    if (c.uplift > 0.0) {
      const float u = float(c.uplift * c.dt);
#pragma omp parallel for schedule(static)
      for (int32_t y = 0; y < g.height; ++y)
        for (int32_t x = 0; x < g.width; ++x) {
          const size_t i = size_t(y) * g.width + x;
          if (g.periodic ? int32_t(i) != sink : !g.on_edge(x, y)) z[i] += u;
        }
    }
    route_filled(g, z, sink, graph);
    accumulate_area(g, graph, area);
    const double kdt = c.k * c.dt;
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i)
      erodibility[i] = float(kdt * (c.m == 0.5 ? std::sqrt(area[i]) : std::pow(area[i], c.m)));
    for (size_t k = 0; k < n; ++k) {
      const int32_t i = graph.stack[k];
      const int32_t r = graph.receiver[i];
      if (r == i || z[i] <= z[r]) continue;
      const float f = erodibility[i] / graph.length[i];
      z[i] = (z[i] + f * z[r]) / (1.0f + f);
    }
    if (c.diffusion > 0.0) hillslope_diffusion(g, z, c.diffusion * c.dt);
    progress.report(double(step + 1) / c.steps);
  }
}

}  // namespace ft::erosion
