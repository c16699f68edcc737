// SPDX-License-Identifier: GPL-3.0-or-later
// Fluvial erosion by the stream-power law dz/dt = U - K A^m S, solved
// implicitly along the stack (Braun & Willett 2013, eq. 8 with n = 1):
//   z_i' = (z_i + F z_r') / (1 + F),  F = K dt A_i^m / L_i,
// where r is i's receiver, already updated because the stack lists it
// first. Unconditionally stable, so a few large steps carve a valley
// network. Depressions are filled before routing (Priority-Flood+epsilon);
// the implicit solve keeps z_i' > z_r' whenever z_i > z_r, so new pits come
// only from diffusion and are rare: the fill (the one O(n log n) part) runs
// only on steps that have them.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

#include "erosion/erosion.hpp"
#include "erosion/flow_graph.hpp"

namespace ft::erosion {
namespace {

// A lake floor: the fill's flat, a few float steps above its receiver.
// Incision there would round the float steps away into exact flats (pits
// again next step), and diffusion would dent it; it is a sediment flat, and
// both leave it alone.
inline bool lake_floor(float zi, float zr) { return zi - zr <= 16.0f * FLT_EPSILON * std::fabs(zi) + FLT_MIN; }

}  // namespace

std::vector<float> uplift_per_step(const D8Grid& g, const float* z0, const FluvialConfig& c) {
  if (!(c.uplift > 0.0)) return {};
  const size_t n = g.size();
  const auto [low, high] = std::minmax_element(z0, z0 + n);
  const float base = *low, top = *high;
  // Uniform, or following the input terrain: a mountain keeps rising where
  // it stands and its plain not at all, so incision carves the landform
  // instead of an uplifted block.
  const double u = c.uplift * c.dt, scale = top > base ? u / (double(top) - base) : 0.0;
  std::vector<float> lift(n);
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < int64_t(n); ++i)
    lift[i] = float(c.uplift_follows_terrain ? scale * (double(z0[i]) - base) : u);
  if (g.periodic) lift[size_t(periodic_sink(g, z0))] = 0.0f;  // the torus's outlet stays
  if (g.sea)
    for (size_t i = 0; i < n; ++i)
      if (g.sea[i]) lift[i] = 0.0f;  // and so does the sea
  return lift;
}

void fluvial(const D8Grid& g, float* z, const FluvialConfig& c, const Progress& progress) {
  const size_t n = g.size();
  FlowGraph graph;
  std::vector<double> area;
  std::vector<float> incision(n);  // K dt A^m, per cell
  std::vector<float> saved(c.diffusion > 0.0 ? n : 0);  // lake floors across diffusion (NaN: not one)
  const int32_t sink = g.periodic ? periodic_sink(g, z) : -1;
  // Base level of a bounded grid: the lowest input height (the sea).
  const float base = *std::min_element(z, z + n);
  const float inv_spacing = float(1.0 / g.spacing);
  const std::vector<float> lift = uplift_per_step(g, z, c);
  for (int32_t step = 0; step < c.steps; ++step) {
    if (!lift.empty()) {
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n); ++i) z[i] += lift[i];
    }
    // Rho8 receivers, drawn anew each step: over a gentle slope D8 would
    // carve one straight channel along the grid direction nearest the fall
    // line; Rho8's paths follow the fall line on average.
    draw_rho8(g, g.periodic ? sink : -1, uint32_t(step), graph);
    {
      const ProgressPart routing(progress, double(step) / c.steps, 0.5 / c.steps);  // its global fill moves the bar
      route_filled(g, z, sink, graph, routing.progress());
    }
    accumulate_area(g, graph, area);
    const double kdt = c.erodibility * c.dt, m = c.area_exponent;
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i)
      incision[i] = float(kdt * (m == 0.5 ? std::sqrt(area[i]) : std::pow(area[i], m)));
    auto edge_f = [&](int32_t i) { return std::min(incision[i] * inv_spacing, kMaxSolveFactor); };
    // Runs of whole trees are independent; each is solved in stack order.
    const int32_t chunks = int32_t(graph.chunk_start.size()) - 1;
#pragma omp parallel for schedule(dynamic, 1)
    for (int32_t ch = 0; ch < chunks; ++ch)
      for (int32_t k = graph.chunk_start[ch]; k < graph.chunk_start[ch + 1]; ++k) {
        const int32_t i = graph.stack[k];
        const int32_t r = graph.receiver[i];
        if (r == i) {
          // An outlet drains to the sea beyond the edge, at the base level one
          // spacing away: edges wear down with the land instead of standing
          // as walls at their fractal heights.
          if (!g.periodic && !g.in_sea(size_t(i)) && z[i] > base)
            z[i] = (z[i] + edge_f(i) * base) / (1.0f + edge_f(i));
          continue;
        }
        if (lake_floor(z[i], z[r])) continue;
        const float f = std::min(incision[i] / graph.length[i], kMaxSolveFactor);
        z[i] = (z[i] + f * z[r]) / (1.0f + f);
      }
    if (c.diffusion > 0.0) {
      // Lake floors keep their height (refilling the dents would cost more
      // than the rest of the step), and so does the sea floor.
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n); ++i) {
        const int32_t r = graph.receiver[i];
        saved[i] = (r != i && lake_floor(z[i], z[r])) || g.in_sea(size_t(i)) ? z[i] : NAN;
      }
      hillslope_diffusion(g, z, c.diffusion * c.dt);
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n); ++i)
        if (!std::isnan(saved[i])) z[i] = saved[i];
    }
    progress.report(double(step + 1) / c.steps);
  }
}

}  // namespace ft::erosion
