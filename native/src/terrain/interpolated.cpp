#include "terrain/interpolated.hpp"

#include <algorithm>
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

// Position of new node i in old-grid node units, split into a node and a
// weight; the tables are per axis, so bilinear interpolation is two lerps.
struct Taps {
  std::vector<int32_t> i0, i1;
  std::vector<float> t;
};
Taps taps(int32_t n_new, int32_t n_old, bool periodic) {
  Taps k;
  k.i0.resize(size_t(n_new));
  k.i1.resize(size_t(n_new));
  k.t.resize(size_t(n_new));
  const double s = periodic ? double(n_old) / n_new : double(n_old - 1) / double(n_new - 1);
  for (int32_t i = 0; i < n_new; ++i) {
    const double p = i * s;
    int32_t a = int32_t(std::floor(p));
    double t = p - a;
    if (!periodic && a >= n_old - 1) a = n_old - 2, t = 1.0;  // the last node, exactly
    k.i0[size_t(i)] = a;
    k.i1[size_t(i)] = periodic ? (a + 1) % n_old : a + 1;
    k.t[size_t(i)] = float(t);
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
#pragma omp parallel num_threads(threads)
    {
      std::vector<float> gauss(size_t(n.nx));
#pragma omp for schedule(static)
      for (int32_t j = 0; j < n.ny; ++j) {
        gaussian_fill(c.seed, Counter{uint32_t(j), uint32_t(cycle), Stream::kInterpolated}, 0, size_t(n.nx),
                      gauss.data());
        const float* r0 = g.z.data() + size_t(ty.i0[size_t(j)]) * g.nx;
        const float* r1 = g.z.data() + size_t(ty.i1[size_t(j)]) * g.nx;
        const float wy = ty.t[size_t(j)];
        float* out = n.z.data() + size_t(j) * n.nx;
        for (int32_t i = 0; i < n.nx; ++i) {
          const int32_t a = tx.i0[size_t(i)], b = tx.i1[size_t(i)];
          const float wx = tx.t[size_t(i)];
          const float top = r0[a] + wx * (r0[b] - r0[a]);
          const float bot = r1[a] + wx * (r1[b] - r1[a]);
          out[i] = (top + wy * (bot - top)) + delta * gauss[size_t(i)];
        }
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
