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
// previous sweep wrote (Jacobi order, rows in parallel, so the result is the
// same on any thread count):
//   sweep 1  the previous pass's sediment transport and evaporation, this
//            pass's rain and outflow fluxes (the fluxes double-buffered: the
//            transport reads the old ones at the neighbours);
//   sweep 2  water depth, velocity, capacity, erosion/deposition, and the
//            fraction of each cell's water that leaves per unit of flux.
// Interior cells take their neighbours at fixed offsets (no edge tests), so
// the inner loops vectorise; edge cells go through the general path.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <vector>

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
  // leave[i] = dt / (cell area x water held before the outflow): the
  // fraction of the cell's water (and sediment) that a unit of flux carries.
  std::vector<float> b, b2, s, s2, d, d2, leave;
  std::vector<float> flux[2][4];
  explicit State(const float* z, size_t n_) : n(n_), b(z, z + n_), b2(n_), s(n_, 0.0f), s2(n_), d(n_, 0.0f), d2(n_),
                                              leave(n_, 0.0f) {
    for (auto& set : flux)
      for (auto& p : set) p.assign(n_, 0.0f);
  }
};

struct Constants {
  float dt, cell_area, accel, inv_l, keep, rain, capacity, dissolve, deposit, min_tilt, max_erosion;
};

// Sweep 1 at cell i. `old` are the previous pass's fluxes, `now` this pass's.
// With `fluxes` false (after the last pass) only transport and evaporation.
template <bool Interior, bool Fluxes>
inline void sweep1_cell(State& st, const Constants& k, const float* const* old, float* const* now, int64_t i,
                        Pipes nb) {
  const float* b = st.b.data();
  const float* d = st.d.data();
  const float* s = st.s.data();
  const float* leave = st.leave.data();
  auto in = [&](int64_t j) { return Interior || j >= 0; };
  // Sediment: what stays plus what the neighbours send back through their
  // pipe towards this cell (east neighbour's west pipe, and so on).
  const float out = old[0][i] + old[1][i] + old[2][i] + old[3][i];
  float gained = 0.0f;
  if (in(nb.e)) gained += old[2][nb.e] * leave[nb.e] * s[nb.e];
  if (in(nb.s)) gained += old[3][nb.s] * leave[nb.s] * s[nb.s];
  if (in(nb.w)) gained += old[0][nb.w] * leave[nb.w] * s[nb.w];
  if (in(nb.n)) gained += old[1][nb.n] * leave[nb.n] * s[nb.n];
  st.s2[i] = s[i] * (1.0f - out * leave[i]) + gained;
  if (!Fluxes) {
    st.d2[i] = d[i] * k.keep;
    return;
  }
  // Water after evaporation and this pass's rain, here and at the neighbours.
  auto water = [&](int64_t j) { return d[j] * k.keep + k.rain; };
  const float di = water(i);
  const float surface = b[i] + di;
  const float others[4] = {in(nb.e) ? b[nb.e] + water(nb.e) : b[i], in(nb.s) ? b[nb.s] + water(nb.s) : b[i],
                           in(nb.w) ? b[nb.w] + water(nb.w) : b[i], in(nb.n) ? b[nb.n] + water(nb.n) : b[i]};
  float f[4], total = 0.0f;
  for (int p = 0; p < 4; ++p) {
    f[p] = std::max(0.0f, old[p][i] + k.accel * (surface - others[p]));
    total += f[p];
  }
  // (No flux: every f[p] is 0 whatever the scale. Branch-free so it vectorises.)
  const float scale = std::min(1.0f, di * k.cell_area / std::max(total * k.dt, FLT_MIN));
  for (int p = 0; p < 4; ++p) now[p][i] = f[p] * scale;
  st.d2[i] = di;
}

// Sweep 2 at cell i: reads this pass's fluxes and the bed; writes b2, the
// cell's own sediment and water (s2, d2, which no neighbour reads in this
// sweep) and leave. Returns the sediment volume sent out of the grid.
template <bool Interior>
inline double sweep2_cell(State& st, const Constants& k, const float* const* now, int64_t i, Pipes nb) {
  const float* b = st.b.data();
  auto in = [&](int64_t j) { return Interior || j >= 0; };
  const float inflow[4] = {in(nb.e) ? now[2][nb.e] : 0.0f, in(nb.s) ? now[3][nb.s] : 0.0f,
                           in(nb.w) ? now[0][nb.w] : 0.0f, in(nb.n) ? now[1][nb.n] : 0.0f};
  const float o[4] = {now[0][i], now[1][i], now[2][i], now[3][i]};
  const float in_total = inflow[0] + inflow[1] + inflow[2] + inflow[3];
  const float out_total = o[0] + o[1] + o[2] + o[3];
  const float before = st.d2[i];
  const float after = std::max(0.0f, before + k.dt * (in_total - out_total) / k.cell_area);
  // Net flow through the cell along x and y (Mei et al. eq. 8-9).
  const float wx = 0.5f * (inflow[2] - o[2] + o[0] - inflow[0]);
  const float wy = 0.5f * (inflow[3] - o[3] + o[1] - inflow[1]);
  const float mean_depth = std::max(0.5f * (before + after), 1e-4f);
  const float speed = std::sqrt(wx * wx + wy * wy) * k.inv_l / mean_depth;
  // Bed gradient by central differences (one-sided at bounded edges).
  const float be = in(nb.e) ? b[nb.e] : b[i], bw = in(nb.w) ? b[nb.w] : b[i];
  const float bs = in(nb.s) ? b[nb.s] : b[i], bn = in(nb.n) ? b[nb.n] : b[i];
  const float gx = (be - bw) * 0.5f * k.inv_l, gy = (bs - bn) * 0.5f * k.inv_l;
  const float grad2 = gx * gx + gy * gy;
  const float tilt = std::max(k.min_tilt, std::sqrt(grad2 / (1.0f + grad2)));
  const float capacity = k.capacity * tilt * speed;
  const float s = st.s2[i];
  // Bed lowering (> 0) or raising (< 0).
  const float change =
      capacity > s ? std::min(k.dissolve * (capacity - s), k.max_erosion) : -k.deposit * (s - capacity);
  st.b2[i] = b[i] - change;
  const float s_new = s + change;
  st.s2[i] = s_new;
  st.d2[i] = after;
  const float held = after + k.dt * out_total / k.cell_area;  // water present before the outflow
  const float per_held = k.dt / (k.cell_area * std::max(held, FLT_MIN));
  const float leave = held > 0.0f ? per_held : 0.0f;
  st.leave[i] = leave;
  if (Interior) return 0.0;
  float lost = 0.0f;  // flux through pipes that leave the grid
  if (nb.e < 0) lost += o[0];
  if (nb.s < 0) lost += o[1];
  if (nb.w < 0) lost += o[2];
  if (nb.n < 0) lost += o[3];
  return double(lost * leave * s_new) * k.cell_area;
}

// Runs `cell(i, pipes)` over row y: the interior with fixed offsets, the
// ends (and whole first/last rows of a bounded grid) through the general
// neighbour lookup.
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
  for (int32_t x = 1; x < w - 1; ++x) interior(row + x, Pipes{row + x + 1, down + x, row + x - 1, up + x});
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
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y) {
      if (last)
        each_in_row(
            g, y, [&](int64_t i, Pipes p) { sweep1_cell<true, false>(st, k, old, now, i, p); },
            [&](int64_t i, Pipes p) { sweep1_cell<false, false>(st, k, old, now, i, p); });
      else
        each_in_row(
            g, y, [&](int64_t i, Pipes p) { sweep1_cell<true, true>(st, k, old, now, i, p); },
            [&](int64_t i, Pipes p) { sweep1_cell<false, true>(st, k, old, now, i, p); });
    }
    if (last) {
      st.s.swap(st.s2);
      st.d.swap(st.d2);
      break;
    }
    // Sweep 2 reads s2 and d2 of the cell itself only, and updates them in place.
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y) {
      double lost = 0.0;
      each_in_row(
          g, y, [&](int64_t i, Pipes p) { sweep2_cell<true>(st, k, now, i, p); },
          [&](int64_t i, Pipes p) { lost += sweep2_cell<false>(st, k, now, i, p); });
      row_out[size_t(y)] += lost;
    }
    st.b.swap(st.b2);
    st.s.swap(st.s2);
    st.d.swap(st.d2);
    progress.report(double(it + 1) / c.iterations);
  }
  // What is still suspended settles where it is.
  for (size_t i = 0; i < n; ++i) z[i] = st.b[i] + st.s[i];
  if (water_out) std::copy(st.d.begin(), st.d.end(), water_out);
  if (budget)
    for (const double v : row_out) budget->carried_out += v;
}

}  // namespace ft::erosion
