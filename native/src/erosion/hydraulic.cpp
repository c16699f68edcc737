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
// Every stage reads the previous stage's arrays (Jacobi order), rows in
// parallel: the result is the same on any thread count.
#include <algorithm>
#include <cmath>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {
namespace {

// Pipes: east, south, west, north (D8 directions 0, 2, 4, 6).
constexpr int kPipe[4] = {0, 2, 4, 6};
constexpr double kGravity = 9.81;

}  // namespace

void hydraulic(const D8Grid& g, float* z, const HydraulicConfig& c, float* water_out, MassBudget* budget,
               const Progress& progress) {
  const size_t n = g.size();
  const int32_t w = g.width, h = g.height;
  // b: the bed; each stage writes arrays no other cell of the stage reads.
  std::vector<float> b(z, z + n), b2(n), d(n, 0.0f), s(n, 0.0f), s2(n), flux(4 * n, 0.0f), frac(4 * n);
  const float dt = float(c.dt);
  const float cell_area = float(g.spacing * g.spacing);
  const float accel = float(c.dt * kGravity * g.spacing);  // dt g A / l with A = l^2
  const float inv_l = float(1.0 / g.spacing);
  const float max_erosion = float(c.max_erosion > 0 ? c.max_erosion : g.spacing / 100);
  double carried_out = 0.0;
  auto nb = [&](int32_t x, int32_t y, int p) { return g.neighbour(x, y, kPipe[p]); };
  for (int32_t it = 0; it < c.iterations; ++it) {
    const float rain = float(c.rain);
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i) d[i] += rain;
    // Outflow fluxes (flux[p * n + i]: volume per second through pipe p).
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        const float surface = b[i] + d[i];
        float f[4], total = 0.0f;
        for (int p = 0; p < 4; ++p) {
          const int64_t j = nb(x, y, p);
          const float other = j < 0 ? b[i] : b[j] + d[j];
          f[p] = std::max(0.0f, flux[p * n + i] + accel * (surface - other));
          total += f[p];
        }
        const float scale = total > 0.0f ? std::min(1.0f, d[i] * cell_area / (total * dt)) : 0.0f;
        for (int p = 0; p < 4; ++p) flux[p * n + i] = f[p] * scale;
      }
    // Water depth, velocity, capacity, erosion/deposition; then the fraction
    // of water (and so of suspended sediment) leaving through each pipe.
#pragma omp parallel for schedule(static) reduction(+ : carried_out)
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        float in[4], out_total = 0.0f, in_total = 0.0f;
        for (int p = 0; p < 4; ++p) {
          const int64_t j = nb(x, y, p);
          in[p] = j < 0 ? 0.0f : flux[((p + 2) & 3) * n + size_t(j)];
          in_total += in[p];
          out_total += flux[p * n + i];
        }
        const float before = d[i];
        const float after = std::max(0.0f, before + dt * (in_total - out_total) / cell_area);
        // Net flow through the cell along x and y (Mei et al. eq. 8-9).
        const float wx = 0.5f * (in[2] - flux[2 * n + i] + flux[0 * n + i] - in[0]);
        const float wy = 0.5f * (in[3] - flux[3 * n + i] + flux[1 * n + i] - in[1]);
        const float mean_depth = std::max(0.5f * (before + after), 1e-4f);
        const float speed = std::hypot(wx, wy) * inv_l / mean_depth;
        // Bed gradient by central differences (one-sided at bounded edges).
        auto bed = [&](int p) {
          const int64_t j = nb(x, y, p);
          return j < 0 ? b[i] : b[j];
        };
        const float gx = (bed(0) - bed(2)) * 0.5f * inv_l, gy = (bed(1) - bed(3)) * 0.5f * inv_l;
        const float grad = std::hypot(gx, gy);
        const float tilt = std::max(float(c.min_tilt), grad / std::sqrt(1.0f + grad * grad));
        const float capacity = float(c.capacity) * tilt * speed;
        float change;  // bed lowering (> 0) or raising (< 0)
        if (capacity > s[i]) change = std::min(float(c.dissolve) * (capacity - s[i]), max_erosion);
        else change = -float(c.deposit) * (s[i] - capacity);
        b2[i] = b[i] - change;
        s[i] += change;
        d[i] = after;
        // Fractions of this cell's water leaving through each pipe this pass.
        const float held = after + dt * out_total / cell_area;  // water present before the outflow
        for (int p = 0; p < 4; ++p) {
          const float fr = held > 0.0f ? dt * flux[p * n + i] / cell_area / held : 0.0f;
          frac[p * n + i] = fr;
          if (nb(x, y, p) < 0) carried_out += double(fr * s[i]) * cell_area;
        }
      }
    b.swap(b2);
    // Suspended sediment moves with the water; evaporation.
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h; ++y)
      for (int32_t x = 0; x < w; ++x) {
        const size_t i = size_t(y) * w + x;
        float left = 1.0f;
        float gained = 0.0f;
        for (int p = 0; p < 4; ++p) {
          left -= frac[p * n + i];
          const int64_t j = nb(x, y, p);
          if (j >= 0) gained += frac[((p + 2) & 3) * n + size_t(j)] * s[j];
        }
        s2[i] = s[i] * left + gained;
        d[i] *= float(1.0 - c.evaporation);
      }
    s.swap(s2);
    progress.report(double(it + 1) / c.iterations);
  }
  // What is still suspended settles where it is.
  for (size_t i = 0; i < n; ++i) z[i] = b[i] + s[i];
  if (water_out) std::copy(d.begin(), d.end(), water_out);
  if (budget) budget->carried_out += carried_out;
}

}  // namespace ft::erosion
