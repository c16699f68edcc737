// SPDX-License-Identifier: GPL-3.0-or-later
// Hydraulic erosion on the grid: the virtual-pipe model (Mei, Decaudin & Hu
// 2007, "Fast Hydraulic Erosion Simulation and Visualization on GPU").
// Each pass: rain; outflow fluxes through four pipes to the neighbours,
// accelerated by the difference in water surface and scaled so no cell
// sends more water than it holds; the water depth update; velocity from the
// net fluxes; sediment capacity C = Kc sin(tilt) |v|, with the bed eroded
// (C above the suspended load) or fed (below); evaporation.
// Mass: Mei et al. move sediment semi-Lagrangian (not conservative). Here
// suspended sediment moves in flux form with the water (each cell sends the
// same fraction of its load through a pipe as of its water), so bed +
// suspended sediment + what left at the edges is constant to rounding.
// Bounded edges are open: outside is the edge cell's bed without water.
//
// Speed: a pass is two sweeps over the grid, each reading only what the
// previous sweep wrote (Jacobi order, so the result is the same on any
// thread count), fused row by row so the grid passes the cache once:
//   sweep 1  the previous pass's sediment transport and evaporation, this
//            pass's rain and outflow fluxes (the fluxes double-buffered: the
//            transport reads the old ones at the neighbours);
//   sweep 2  water depth, velocity, capacity, erosion/deposition, and the
//            sediment each cell sends per unit of flux.
// Interior cells take their neighbours at fixed offsets (no edge tests), so
// the inner loops vectorise; edge cells go through the general path. The
// interior sweeps are built three times, for AVX-512 (x86-64-v4), AVX2 and
// the baseline, chosen at load time: none fuses a multiply and an add
// (-ffp-contract=off), so all give the same bits (checked by comparing a
// 513^2 terrain eroded by the Land preset with the clones removed, and 13
// eroded terrains from the AVX-512 and the AVX2 path: identical files).
// AVX2 makes the passes 1.5x faster than the baseline; AVX-512 (its 32
// registers) 7% faster again on a Zen 4.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <omp.h>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/buffer.hpp"
#include "core/kernel_clones.hpp"
#include "erosion/erosion.hpp"


namespace ft::erosion {
namespace {

constexpr double kGravity = 9.81;

// Neighbours of a cell through the four pipes (east, south, west, north), -1
// outside a bounded grid.
struct Pipes {
  int64_t e, s, w, n;
};

struct State {
  size_t n;
  // bed, suspended sediment and water (two buffers where a sweep writes
  // what its neighbours read), fluxes per pipe (current and previous), and
  // sent[i] = dt x sediment / (cell area x water held before the outflow):
  // fraction of the cell's water (and sediment) that a unit of flux carries.
  // Buffers (huge pages, not zeroed on allocation) set by the team: 16
  // std::vectors were 67 MB zeroed by one thread, page by page, at 1025^2.
  Buffer<float> b, b2, s, s2, d, d2, sent;
  Buffer<float> flux[2][4];
  State(const float* z, size_t n_) : n(n_), b(n_), b2(n_), s(n_), s2(n_), d(n_), d2(n_), sent(n_) {
    for (auto& set : flux)
      for (auto& p : set) p = Buffer<float>(n_);
    const int64_t cells = int64_t(n_);
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < cells; ++i) {
      b[i] = z[i];
      s[i] = d[i] = sent[i] = 0.0f;
      for (auto& set : flux)
        for (auto& p : set) p[i] = 0.0f;
      b2[i] = s2[i] = d2[i] = 0.0f;  // written before read; set here so the team touches their pages
    }
  }
};

struct Constants {
  float dt, cell_area, accel, inv_l, keep, rain, capacity, dissolve, deposit, min_tilt, max_erosion;
};

// Four values, one per pipe (east, south, west, north). Passed by value, so
// the vectoriser sees scalars, not a local array in memory.
struct Four {
  float e, s, w, n;
  float sum() const { return e + s + w + n; }
};

// The physics of one cell, on values: the sweeps gather them from the grid
// (interior cells at fixed offsets, edge cells through the neighbour
// lookup) and call these, so both paths compute the same thing.

// Suspended sediment after the transport: what stays plus what the
// neighbours send through their pipes towards this cell.
inline float transported(float s, float out, float sent, float gained) { return s - out * sent + gained; }

// Outflow fluxes of a cell holding `di` water (after rain) with water
// surface `surface`, beside surfaces `other` (east, south, west, north).
inline Four outflow(const Constants& k, float surface, float di, Four other, Four old) {
    const Four f = {std::max(0.0f, old.e + k.accel * (surface - other.e)),
                  std::max(0.0f, old.s + k.accel * (surface - other.s)),
                  std::max(0.0f, old.w + k.accel * (surface - other.w)),
                  std::max(0.0f, old.n + k.accel * (surface - other.n))};
  const float total = f.sum();
  // (No flux: every f is 0 whatever the scale. Branch-free so it vectorises.)
  const float scale = std::min(1.0f, di * k.cell_area / std::max(total * k.dt, FLT_MIN));
  return {f.e * scale, f.s * scale, f.w * scale, f.n * scale};
}

struct Updated {
  float bed, sediment, water, sent;
};

// Water depth, velocity, capacity and erosion/deposition of a cell with
// water `before`, outflows `o` and inflows `in` (by pipe), bed `b` beside
// beds `be, bw, bs, bn` and suspended sediment `s`.
inline Updated update(const Constants& k, float before, Four in, Four o, float b, float be, float bw, float bs,
                      float bn, float s) {
  const float in_total = in.sum();
  const float out_total = o.sum();
  const float after = std::max(0.0f, before + k.dt * (in_total - out_total) / k.cell_area);
  // Net flow through the cell along x and y (Mei et al. eq. 8-9).
  const float wx = 0.5f * (in.w - o.w + o.e - in.e);
  const float wy = 0.5f * (in.n - o.n + o.s - in.s);
  const float mean_depth = std::max(0.5f * (before + after), 1e-4f);
  const float speed = std::sqrt(wx * wx + wy * wy) * k.inv_l / mean_depth;
  // Bed gradient by central differences (one-sided at bounded edges).
  const float gx = (be - bw) * 0.5f * k.inv_l, gy = (bs - bn) * 0.5f * k.inv_l;
  const float grad2 = gx * gx + gy * gy;
  const float tilt = std::max(k.min_tilt, std::sqrt(grad2 / (1.0f + grad2)));
  const float capacity = k.capacity * tilt * speed;
  // Bed lowering (> 0: capacity above the load, at most max_erosion) or
  // raising (< 0). As min/max, not a branch, so the loops vectorise.
  const float excess = capacity - s;
  const float change =
      std::min(k.dissolve * std::max(excess, 0.0f), k.max_erosion) + k.deposit * std::min(excess, 0.0f);
  // Water present before the outflow. A dry cell (held = 0) has no outflow,
  // so any finite `leave` sends nothing: capped, not branched on.
  const float held = after + k.dt * out_total / k.cell_area;
  const float leave = std::min(k.dt / (k.cell_area * std::max(held, FLT_MIN)), FLT_MAX);
  // Sediment sent per unit of flux, capped too: a dry cell's 0 flux times
  // FLT_MAX is 0, where infinity would give NaN.
  return {b - change, s + change, after, std::min(leave * (s + change), FLT_MAX)};
}

// Sweep 1 over the interior cells x0 .. x1 - 1 of a row (`row`, `up`, `down`:
// indices of the rows' first cells). `old` are the previous pass's fluxes,
// `now` this pass's. Without `Fluxes` (after the last pass) only transport
// and evaporation.
// The arrays are restrict parameters of a function that is not inlined:
// GCC keeps restrict only on parameters, and without it the loop needs more
// alias checks than it will version for, and does not vectorise.
template <bool Fluxes>
[[gnu::noinline]] FT_KERNEL_CLONES void sweep1_interior(const Constants k, int64_t row, int64_t up, int64_t down, int32_t x0,
                                       int32_t x1, const float* __restrict b, const float* __restrict d,
                                       const float* __restrict s, const float* __restrict sent,
                                       const float* __restrict o0, const float* __restrict o1,
                                       const float* __restrict o2, const float* __restrict o3, float* __restrict n0,
                                       float* __restrict n1, float* __restrict n2, float* __restrict n3,
                                       float* __restrict s2, float* __restrict d2) {
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x, e = i + 1, w = i - 1, n = up + x, so = down + x;
    const float out = o0[i] + o1[i] + o2[i] + o3[i];
    const float gained = o2[e] * sent[e] + o3[so] * sent[so] + o0[w] * sent[w] + o1[n] * sent[n];
    s2[i] = transported(s[i], out, sent[i], gained);
    if (!Fluxes) {
      d2[i] = d[i] * k.keep;
      continue;
    }
    const float di = d[i] * k.keep + k.rain;
    const Four other = {b[e] + (d[e] * k.keep + k.rain), b[so] + (d[so] * k.keep + k.rain),
                        b[w] + (d[w] * k.keep + k.rain), b[n] + (d[n] * k.keep + k.rain)};
    const Four f = outflow(k, b[i] + di, di, other, Four{o0[i], o1[i], o2[i], o3[i]});
    n0[i] = f.e, n1[i] = f.s, n2[i] = f.w, n3[i] = f.n;
    d2[i] = di;
  }
}

// Sweep 1 at an edge cell (neighbours -1 outside a bounded grid: there the
// other side is the cell's bed without water).
template <bool Fluxes>
void sweep1_edge(State& st, const Constants& k, const float* const* old, float* const* now, int64_t i, Pipes nb) {
  const float* b = st.b.data();
  const float* d = st.d.data();
  const float* s = st.s.data();
  const float* sent = st.sent.data();
  const float out = old[0][i] + old[1][i] + old[2][i] + old[3][i];
  float gained = 0.0f;
  if (nb.e >= 0) gained += old[2][nb.e] * sent[nb.e];
  if (nb.s >= 0) gained += old[3][nb.s] * sent[nb.s];
  if (nb.w >= 0) gained += old[0][nb.w] * sent[nb.w];
  if (nb.n >= 0) gained += old[1][nb.n] * sent[nb.n];
  st.s2[i] = transported(s[i], out, sent[i], gained);
  if (!Fluxes) {
    st.d2[i] = d[i] * k.keep;
    return;
  }
  auto surface = [&](int64_t j) { return j >= 0 ? b[j] + (d[j] * k.keep + k.rain) : b[i]; };
  const float di = d[i] * k.keep + k.rain;
  const Four f = outflow(k, b[i] + di, di, Four{surface(nb.e), surface(nb.s), surface(nb.w), surface(nb.n)},
                        Four{old[0][i], old[1][i], old[2][i], old[3][i]});
  now[0][i] = f.e, now[1][i] = f.s, now[2][i] = f.w, now[3][i] = f.n;
  st.d2[i] = di;
}

// Sweep 2 over interior cells: reads this pass's fluxes and the bed; writes
// b2, the cells' own sediment and water (s2, d2, which no neighbour reads
// in this sweep) and sent.
[[gnu::noinline]] FT_KERNEL_CLONES void sweep2_interior(const Constants k, int64_t row, int64_t up, int64_t down, int32_t x0,
                                       int32_t x1, const float* __restrict b, const float* __restrict f0,
                                       const float* __restrict f1, const float* __restrict f2,
                                       const float* __restrict f3, float* __restrict b2, float* __restrict s2,
                                       float* __restrict d2, float* __restrict sent) {
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x, e = i + 1, w = i - 1, n = up + x, so = down + x;
    const Updated u = update(k, d2[i], Four{f2[e], f3[so], f0[w], f1[n]}, Four{f0[i], f1[i], f2[i], f3[i]}, b[i],
                             b[e], b[w], b[so], b[n], s2[i]);
    b2[i] = u.bed;
    s2[i] = u.sediment;
    d2[i] = u.water;
    sent[i] = u.sent;
  }
}

// Sweep 2 at an edge cell; returns the sediment volume sent out of the grid.
double sweep2_edge(State& st, const Constants& k, const float* const* now, int64_t i, Pipes nb) {
  const float* b = st.b.data();
  auto flux_in = [&](int64_t j, int p) { return j >= 0 ? now[p][j] : 0.0f; };
  auto bed = [&](int64_t j) { return j >= 0 ? b[j] : b[i]; };
  const Four in = {flux_in(nb.e, 2), flux_in(nb.s, 3), flux_in(nb.w, 0), flux_in(nb.n, 1)};
  const Four o = {now[0][i], now[1][i], now[2][i], now[3][i]};
  const Updated u = update(k, st.d2[i], in, o, b[i], bed(nb.e), bed(nb.w), bed(nb.s), bed(nb.n), st.s2[i]);
  st.b2[i] = u.bed;
  st.s2[i] = u.sediment;
  st.d2[i] = u.water;
  st.sent[i] = u.sent;
  float lost = 0.0f;  // flux through pipes that leave the grid
  if (nb.e < 0) lost += o.e;
  if (nb.s < 0) lost += o.s;
  if (nb.w < 0) lost += o.w;
  if (nb.n < 0) lost += o.n;
  return double(lost * u.sent) * k.cell_area;
}

// Row y: `interior(row, up, down, x0, x1)` over the cells with four
// neighbours at fixed offsets, `edge(i, pipes)` on the others (the ends,
// and the first and last rows of a bounded grid).
template <class Interior, class Edge>
inline void each_in_row(const D8Grid& g, int32_t y, Interior&& interior, Edge&& edge) {
  const int32_t w = g.width;
  const int64_t row = int64_t(y) * w;
  auto general = [&](int32_t x) {
    edge(row + x, Pipes{g.neighbour(x, y, 0), g.neighbour(x, y, 2), g.neighbour(x, y, 4), g.neighbour(x, y, 6)});
  };
  const bool inner_row = g.periodic || (y > 0 && y < g.height - 1);
  if (!inner_row) {
    for (int32_t x = 0; x < w; ++x) general(x);
    return;
  }
  // Rows above and below (wrapped on a torus).
  const int64_t up = (y > 0 ? y - 1 : g.height - 1) * int64_t(w), down = (y < g.height - 1 ? y + 1 : 0) * int64_t(w);
  general(0);
  interior(row, up, down, 1, w - 1);
  general(w - 1);
}

}  // namespace

void hydraulic(const D8Grid& g, float* z, const HydraulicConfig& c, float* water_out, MassBudget* budget,
               const Progress& progress) {
  const size_t n = g.size();
  const int32_t h = g.height;
  State st(z, n);
  Constants k;
  k.dt = float(c.dt);
  k.cell_area = float(g.spacing * g.spacing);
  k.accel = float(c.dt * kGravity * g.spacing);  // dt g A / l with A = l^2
  k.inv_l = float(1.0 / g.spacing);
  k.keep = float(1.0 - c.evaporation);
  k.rain = float(c.rain);
  k.capacity = float(c.capacity);
  k.dissolve = float(c.dissolve);
  k.deposit = float(c.deposit);
  k.min_tilt = float(c.min_tilt);
  k.max_erosion = float(c.max_erosion > 0 ? c.max_erosion : g.spacing / 100);
  // Sediment leaving per row, summed in row order afterwards (the same sum
  // on any thread count).
  std::vector<double> row_out(size_t(h), 0.0);
  int cur = 0;  // st.flux[cur]: this pass's fluxes
  for (int32_t it = 0; it <= c.iterations; ++it) {
    const bool last = it == c.iterations;  // only the transport of the last pass is left
    cur = it & 1;
    const float* old[4] = {st.flux[1 - cur][0].data(), st.flux[1 - cur][1].data(), st.flux[1 - cur][2].data(),
                           st.flux[1 - cur][3].data()};
    float* now[4] = {st.flux[cur][0].data(), st.flux[cur][1].data(), st.flux[cur][2].data(),
                     st.flux[cur][3].data()};
    auto sweep1 = [&](int32_t y, auto fluxes) {
      constexpr bool F = decltype(fluxes)::value;
      each_in_row(
          g, y,
          [&](int64_t row, int64_t up, int64_t down, int32_t x0, int32_t x1) {
            sweep1_interior<F>(k, row, up, down, x0, x1, st.b.data(), st.d.data(), st.s.data(), st.sent.data(),
                               old[0], old[1], old[2], old[3], now[0], now[1], now[2], now[3], st.s2.data(),
                               st.d2.data());
          },
          [&](int64_t i, Pipes p) { sweep1_edge<F>(st, k, old, now, i, p); });
    };
    if (last) {
#pragma omp parallel for schedule(static)
      for (int32_t y = 0; y < h; ++y) sweep1(y, std::false_type{});
      std::swap(st.s, st.s2);
      std::swap(st.d, st.d2);
      break;
    }
    // Sweep 2 reads s2 and d2 of the cell itself only, and updates them in
    // place; it writes `sent` in place too, which sweep 1 reads at the
    // rows beside.
    auto sweep2 = [&](int32_t y) {
      double lost = 0.0;
      each_in_row(
          g, y,
          [&](int64_t row, int64_t up, int64_t down, int32_t x0, int32_t x1) {
            sweep2_interior(k, row, up, down, x0, x1, st.b.data(), now[0], now[1], now[2], now[3], st.b2.data(),
                            st.s2.data(), st.d2.data(), st.sent.data());
          },
          [&](int64_t i, Pipes p) { lost += sweep2_edge(st, k, now, i, p); });
      row_out[size_t(y)] += lost;
    };
    // The two sweeps fused row by row, so a pass streams the grid through
    // the cache once instead of twice: sweep 1 of row y + 1, then sweep 2 of
    // row y (which needs sweep 1 of rows y - 1 .. y + 1, and overwrites the
    // `sent` of row y that sweep 1 of row y + 1 has just read). Each thread
    // takes a band of rows; sweep 1 of a band's first and last rows, which
    // the next bands read and whose neighbours they overwrite, runs before
    // a barrier. Every cell is computed by the same formulas whatever the
    // bands: the same result on any thread count.
#pragma omp parallel
    {
      const int32_t t = omp_get_thread_num(), threads = omp_get_num_threads();
      const int32_t y0 = int32_t(int64_t(h) * t / threads), y1 = int32_t(int64_t(h) * (t + 1) / threads);
      if (y1 > y0) {
        sweep1(y0, std::true_type{});
        if (y1 - 1 > y0) sweep1(y1 - 1, std::true_type{});
      }
#pragma omp barrier
      for (int32_t y = y0; y < y1; ++y) {
        if (y + 1 < y1 - 1) sweep1(y + 1, std::true_type{});
        sweep2(y);
      }
    }
    std::swap(st.b, st.b2);
    std::swap(st.s, st.s2);
    std::swap(st.d, st.d2);
    progress.report(double(it + 1) / c.iterations);
  }
  // What is still suspended settles where it is.
  const int64_t cells = int64_t(n);
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < cells; ++i) {
    z[i] = st.b[i] + st.s[i];
    if (water_out) water_out[i] = st.d[i];
  }
  if (budget)
    for (const double v : row_out) budget->carried_out += v;
}

}  // namespace ft::erosion
