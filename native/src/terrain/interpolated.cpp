// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/interpolated.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "core/buffer.hpp"
#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace ft::terrain {
namespace {

// A grid of nx x ny nodes over the terrain. Non-periodic: nodes at
// k (W - 1) / (nx - 1), spanning the samples exactly. Periodic: nodes at
// k W / nx, and node nx is node 0 again.
struct Grid {
  int32_t nx = 0, ny = 0;
  Buffer<float> z;
};

// Nodes per axis for a nominal spacing `d` over `n` samples.
int32_t nodes_for(int32_t n, double d, bool periodic) {
  if (periodic) return int32_t(std::clamp(std::round(n / d), 1.0, double(n)));
  return int32_t(std::clamp(std::ceil((n - 1) / d - 1e-9), 1.0, double(n - 1))) + 1;
}

// Catmull-Rom taps of new node i on the old grid, per axis: four old
// nodes and their weights. Cubic rather than (bi)linear interpolation: linear
// interpolation leaves a crease along every old grid line (the artefact Feder
// notes for the plain additions); Catmull-Rom is C1 and still passes through
// the old nodes. Non-periodic grids clamp at the border, periodic ones wrap.
struct Tap {
  std::array<int32_t, 4> idx;
  std::array<float, 4> w;
};
Tap tap(int32_t i, int32_t n_new, int32_t n_old, bool periodic) {
  Tap k;
  const double s = periodic ? double(n_old) / n_new : double(n_old - 1) / double(n_new - 1);
  const double p = i * s;
  int32_t a = int32_t(std::floor(p));
  double t = p - a;
  if (!periodic && a >= n_old - 1) a = n_old - 1, t = 0.0;  // the last node, exactly
  for (int q = 0; q < 4; ++q) {
    int32_t m = a - 1 + q;
    m = periodic ? ((m % n_old) + n_old) % n_old : std::clamp(m, 0, n_old - 1);
    k.idx[size_t(q)] = m;
  }
  const double t2 = t * t, t3 = t2 * t;
  k.w = {float(0.5 * (-t3 + 2 * t2 - t)), float(0.5 * (3 * t3 - 5 * t2 + 2)), float(0.5 * (-3 * t3 + 4 * t2 + t)),
         float(0.5 * (t3 - t2))};
  return k;
}

// One cycle that changes the grid: its number (the random streams' level),
// node counts and the std of its Gaussians.
struct Cycle {
  int number;
  int32_t nx, ny;
  float delta;
};

// One axis of a window: the nodes of one cycle that the window needs
// (sorted), and for each the taps into the previous cycle's needed nodes,
// as positions in that list.
struct AxisPlan {
  std::vector<int32_t> nodes;
  std::vector<Tap> taps;  // idx are positions in the previous cycle's `nodes`
};

// Nodes [first, first + count) of the last cycle and, walking back, the
// nodes each earlier cycle must provide: at cycle k, the taps of cycle
// k + 1's needed nodes. A window of w samples needs about w / lacunarity^j
// + 4 nodes j cycles back, so the work is that of the window.
std::vector<AxisPlan> plan_axis(const std::vector<int32_t>& counts, int64_t first, int32_t count, bool periodic) {
  std::vector<AxisPlan> plan(counts.size());
  auto& last = plan.back().nodes;
  last.resize(size_t(count));
  for (int32_t i = 0; i < count; ++i) last[size_t(i)] = int32_t(first + i);
  for (size_t k = counts.size() - 1; k > 0; --k) {
    std::vector<int32_t>& old = plan[k - 1].nodes;
    for (int32_t i : plan[k].nodes)
      for (int32_t m : tap(i, counts[k], counts[k - 1], periodic).idx) old.push_back(m);
    std::sort(old.begin(), old.end());
    old.erase(std::unique(old.begin(), old.end()), old.end());
    plan[k].taps.reserve(plan[k].nodes.size());
    for (int32_t i : plan[k].nodes) {
      Tap t = tap(i, counts[k], counts[k - 1], periodic);
      for (int32_t& m : t.idx) m = int32_t(std::lower_bound(old.begin(), old.end(), m) - old.begin());
      plan[k].taps.push_back(t);
    }
  }
  return plan;
}

// N(0, 1) draws of row `row` of cycle `cycle` at the listed node indices,
// one fill per run of consecutive indices.
void node_draws(const InterpolatedConfig& c, uint32_t row, int cycle, const std::vector<int32_t>& nodes,
                float* out) {
  for (size_t a = 0; a < nodes.size();) {
    size_t b = a + 1;
    while (b < nodes.size() && nodes[b] == nodes[b - 1] + 1) ++b;
    gaussian_fill(c.seed, Counter{row, uint32_t(cycle), Stream::kInterpolated}, uint64_t(nodes[a]), b - a, out + a);
    a = b;
  }
}

}  // namespace

void check_interpolated_lacunarity(double lacunarity) {
  if (!(lacunarity > 1.0 && lacunarity <= kMaxInterpolatedLacunarity))
    invalid("lacunarity (the scale factor 1/r per cycle of the interpolated method) must be in (1, 16], got " +
            format_number(lacunarity));
}

Heightfield interpolated_fm(const InterpolatedConfig& c) {
  // Peak use, last cycle: the old grid, the x-interpolated rows, the new
  // grid and the returned copy, under 3 x W x H floats in all.
  check_allocation(checked_bytes(uint64_t(c.width), uint64_t(c.height), 3 * sizeof(float)),
                   "the interpolated method's grids for a " + std::to_string(c.width) + " x " +
                       std::to_string(c.height) + " terrain");
  return interpolated_window(c, 0, 0, c.width, c.height);
}

Heightfield interpolated_window(const InterpolatedConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h) {
  const bool per = c.periodic;
  const int threads = resolve_threads(c.threads);
  const double d0 = per ? std::max(c.width, c.height) : std::max(c.width - 1, c.height - 1);
  // The cycles that change the grid. Cycle 0: the corners (one node per
  // axis when periodic: a constant).
  std::vector<Cycle> cycles{{0, nodes_for(c.width, d0, per), nodes_for(c.height, d0, per), 0.0f}};
  const int count = std::max(1, int(std::ceil(std::log(d0) / std::log(c.lacunarity) - 1e-9)));
  double d = d0;
  for (int cycle = 1; cycle <= count; ++cycle) {
    d = cycle == count ? 1.0 : d / c.lacunarity;
    const int32_t nx = cycle == count ? c.width : nodes_for(c.width, d, per);
    const int32_t ny = cycle == count ? c.height : nodes_for(c.height, d, per);
    // The spacing did not change the node count yet (tiny steps near the start).
    if (nx == cycles.back().nx && ny == cycles.back().ny && cycle != count) continue;
    // fBm's increments scale as spacing^H: the Gaussians added at spacing d
    // have std sigma (d / d0)^H, the same law as Voss's delta_n.
    cycles.push_back({cycle, nx, ny, float(c.sigma * std::pow(d / d0, c.hurst))});
  }
  std::vector<int32_t> xs, ys;
  for (const Cycle& k : cycles) xs.push_back(k.nx), ys.push_back(k.ny);
  const std::vector<AxisPlan> px = plan_axis(xs, x0, w, per), py = plan_axis(ys, y0, h, per);

  // Cycle 0's needed corners.
  size_t gx = px[0].nodes.size(), gy = py[0].nodes.size();
  Buffer<float> g(gx * gy);
  for (size_t j = 0; j < gy; ++j)
    for (size_t i = 0; i < gx; ++i)
      g[j * gx + i] = gaussian_at(c.seed, Counter{0, 0, Stream::kInterpolated},
                                  uint64_t(py[0].nodes[j]) * uint64_t(xs[0]) + uint64_t(px[0].nodes[i])) *
                      float(c.sigma);
  for (size_t k = 1; k < cycles.size(); ++k) {
    const AxisPlan &ax = px[k], &ay = py[k];
    const size_t nx = ax.nodes.size(), ny = ay.nodes.size();
    Buffer<float> n(nx * ny);
    const float delta = cycles[k].delta;
    // Separable: the old rows interpolated along x first, then along y.
    Buffer<float> tmp(gy * nx);
#pragma omp parallel num_threads(threads)
    {
#pragma omp for schedule(static)
      for (size_t j = 0; j < gy; ++j) {
        const float* src = g.data() + j * gx;
        float* dst = tmp.data() + j * nx;
        for (size_t i = 0; i < nx; ++i) {
          const auto& ix = ax.taps[i].idx;
          const auto& wt = ax.taps[i].w;
          dst[i] = (wt[0] * src[ix[0]] + wt[1] * src[ix[1]]) + (wt[2] * src[ix[2]] + wt[3] * src[ix[3]]);
        }
      }
      std::vector<float> gauss(nx);
#pragma omp for schedule(static)
      for (size_t j = 0; j < ny; ++j) {
        node_draws(c, uint32_t(ay.nodes[j]), cycles[k].number, ax.nodes, gauss.data());
        const auto& iy = ay.taps[j].idx;
        const auto& wt = ay.taps[j].w;
        const float* r0 = tmp.data() + size_t(iy[0]) * nx;
        const float* r1 = tmp.data() + size_t(iy[1]) * nx;
        const float* r2 = tmp.data() + size_t(iy[2]) * nx;
        const float* r3 = tmp.data() + size_t(iy[3]) * nx;
        float* out = n.data() + j * nx;
        for (size_t i = 0; i < nx; ++i)
          out[i] = ((wt[0] * r0[i] + wt[1] * r1[i]) + (wt[2] * r2[i] + wt[3] * r3[i])) + delta * gauss[i];
      }
    }
    g = std::move(n);
    gx = nx, gy = ny;
    c.progress.report(double(k) / double(cycles.size() - 1));
  }
  Heightfield hf(w, h);
  std::copy(g.data(), g.data() + size_t(w) * size_t(h), hf.data());
  return hf;
}

}  // namespace ft::terrain
