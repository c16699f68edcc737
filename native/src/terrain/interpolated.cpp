#include "terrain/interpolated.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/buffer.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace ft {
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
struct Taps {
  std::vector<std::array<int32_t, 4>> idx;
  std::vector<std::array<float, 4>> w;
};
Taps taps(int32_t n_new, int32_t n_old, bool periodic) {
  Taps k;
  k.idx.resize(size_t(n_new));
  k.w.resize(size_t(n_new));
  const double s = periodic ? double(n_old) / n_new : double(n_old - 1) / double(n_new - 1);
  for (int32_t i = 0; i < n_new; ++i) {
    const double p = i * s;
    int32_t a = int32_t(std::floor(p));
    double t = p - a;
    if (!periodic && a >= n_old - 1) a = n_old - 1, t = 0.0;  // the last node, exactly
    for (int q = 0; q < 4; ++q) {
      int32_t m = a - 1 + q;
      m = periodic ? ((m % n_old) + n_old) % n_old : std::clamp(m, 0, n_old - 1);
      k.idx[size_t(i)][size_t(q)] = m;
    }
    const double t2 = t * t, t3 = t2 * t;
    k.w[size_t(i)] = {float(0.5 * (-t3 + 2 * t2 - t)), float(0.5 * (3 * t3 - 5 * t2 + 2)),
                      float(0.5 * (-3 * t3 + 4 * t2 + t)), float(0.5 * (t3 - t2))};
  }
  return k;
}

}  // namespace

void check_interpolated_lacunarity(double lacunarity) {
  if (!(lacunarity > 1.0 && lacunarity <= kMaxInterpolatedLacunarity))
    invalid("lacunarity (the scale factor 1/r per cycle of the interpolated method) must be in (1, 16], got " +
            format_number(lacunarity));
}

Heightfield interpolated_fm(const InterpolatedConfig& c) {
  const bool per = c.periodic;
  const int threads = resolve_threads(c.threads);
  const double d0 = per ? std::max(c.width, c.height) : std::max(c.width - 1, c.height - 1);
  // Cycle 0: the corners (one node per axis when periodic: a constant).
  Grid g;
  g.nx = nodes_for(c.width, d0, per);
  g.ny = nodes_for(c.height, d0, per);
  g.z = Buffer<float>(size_t(g.nx) * g.ny);
  gaussian_fill(c.seed, Counter{0, 0, Stream::kInterpolated}, 0, g.z.size(), g.z.data());
  for (float& v : g.z) v *= float(c.sigma);

  const int cycles = std::max(1, int(std::ceil(std::log(d0) / std::log(c.lacunarity) - 1e-9)));
  double d = d0;
  for (int cycle = 1; cycle <= cycles; ++cycle) {
    d = cycle == cycles ? 1.0 : d / c.lacunarity;
    Grid n;
    n.nx = cycle == cycles ? c.width : nodes_for(c.width, d, per);
    n.ny = cycle == cycles ? c.height : nodes_for(c.height, d, per);
    if (n.nx == g.nx && n.ny == g.ny && cycle != cycles) {
      // The spacing did not change the node count yet (tiny steps near the start).
      continue;
    }
    n.z = Buffer<float>(size_t(n.nx) * n.ny);
    const Taps tx = taps(n.nx, g.nx, per), ty = taps(n.ny, g.ny, per);
    // fBm's increments scale as spacing^H: the Gaussians added at spacing d
    // have std sigma (d / d0)^H, the same law as Voss's delta_n.
    const float delta = float(c.sigma * std::pow(d / d0, c.hurst));
    // Separable: the old rows interpolated along x first, then along y.
    Buffer<float> tmp(size_t(g.ny) * n.nx);
#pragma omp parallel num_threads(threads)
    {
#pragma omp for schedule(static)
      for (int32_t j = 0; j < g.ny; ++j) {
        const float* src = g.z.data() + size_t(j) * g.nx;
        float* dst = tmp.data() + size_t(j) * n.nx;
        for (int32_t i = 0; i < n.nx; ++i) {
          const auto& ix = tx.idx[size_t(i)];
          const auto& w = tx.w[size_t(i)];
          dst[i] = (w[0] * src[ix[0]] + w[1] * src[ix[1]]) + (w[2] * src[ix[2]] + w[3] * src[ix[3]]);
        }
      }
      std::vector<float> gauss(size_t(n.nx));
#pragma omp for schedule(static)
      for (int32_t j = 0; j < n.ny; ++j) {
        gaussian_fill(c.seed, Counter{uint32_t(j), uint32_t(cycle), Stream::kInterpolated}, 0, size_t(n.nx),
                      gauss.data());
        const auto& iy = ty.idx[size_t(j)];
        const auto& w = ty.w[size_t(j)];
        const float* r0 = tmp.data() + size_t(iy[0]) * n.nx;
        const float* r1 = tmp.data() + size_t(iy[1]) * n.nx;
        const float* r2 = tmp.data() + size_t(iy[2]) * n.nx;
        const float* r3 = tmp.data() + size_t(iy[3]) * n.nx;
        float* out = n.z.data() + size_t(j) * n.nx;
        for (int32_t i = 0; i < n.nx; ++i)
          out[i] = ((w[0] * r0[i] + w[1] * r1[i]) + (w[2] * r2[i] + w[3] * r3[i])) + delta * gauss[size_t(i)];
      }
    }
    g = std::move(n);
    c.progress.report(double(cycle) / cycles);
  }
  Heightfield hf(c.width, c.height);
  std::copy(g.z.data(), g.z.data() + g.z.size(), hf.data());
  return hf;
}

}  // namespace ft
