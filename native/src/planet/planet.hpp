// SPDX-License-Identifier: GPL-3.0-or-later
// A fractal planet in metres above the radius, with a sea: fBm on the unit
// sphere (noise/fbm3.hpp), a function of the 3D point only, so every layout
// (cube_sphere.hpp, equirect.hpp, icosphere.hpp) and every patch gives the
// bits of the same planet; or midpoint displacement on the cube-sphere
// (midpoint_sphere.hpp), whose heights are the cube-sphere's samples (the
// other layouts interpolate them, cube_sampler.hpp). Any thread count.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>
#include <functional>
#include <limits>

#include "core/buffer.hpp"
#include "core/parallel_rows.hpp"
#include "core/progress.hpp"
#include "noise/fbm3.hpp"
#include "planet/midpoint_sphere.hpp"

namespace ft::planet {

enum Method : int32_t { kMethodFbm = 0, kMethodMidpoint = 1 };
// The values of FT_PLANET_SEA_* (planet.h) and terrain.h's FT_SEA_*.
enum Sea : int32_t { kSeaNone = 0, kSeaHeight = 1, kSeaFraction = 2 };

// Points of the Fibonacci sphere whose height quantile is a sea fraction's level.
inline constexpr int kSeaQuantilePoints = 1 << 16;
// The level of a midpoint planet's cube-sphere those points are interpolated from.
inline constexpr int kSeaQuantileLevel = 8;

// n unit vectors as three arrays, the form Planet::heights takes. Not
// zero-filled: its maker sets every direction (a mesh's in parallel rows).
struct Directions {
  Buffer<double> x, y, z;
  explicit Directions(size_t n) : x(n), y(n), z(n) {}
  void set(size_t i, const std::array<double, 3>& p) { x[i] = p[0], y[i] = p[1], z[i] = p[2]; }
  int64_t size() const { return int64_t(x.size()); }
};

struct PlanetConfig {
  int32_t method = kMethodFbm;
  double radius = 6371000.0;  // metres, > 0
  noise::Fbm3Config fbm = {.sigma = 4000.0};  // sigma in metres
  int32_t sea = kSeaNone;
  double sea_level = 0.0;     // kSeaHeight: metres above the radius
  double sea_fraction = 0.7;  // kSeaFraction: share of the area, [0, 1)
  int threads = 0;
  Progress progress;
};

// Throws ft::Error naming the field and its allowed range.
void validate_planet(const PlanetConfig& c);

class Planet {
 public:
  explicit Planet(const PlanetConfig& c);  // validates; finds the sea's level
  bool midpoint() const { return config_.method == kMethodMidpoint; }
  MidpointConfig midpoint_config() const { return {config_.fbm.sigma, config_.fbm.hurst, config_.fbm.seed}; }
  // Heights (metres) at n unit vectors; any n; the sea applied. fBm only: a
  // midpoint planet is refused (its heights are its cube-sphere samples).
  void heights(int64_t n, const double* x, const double* y, const double* z, float* out) const;
  void heights(const Directions& d, float* out) const { heights(d.size(), d.x.data(), d.y.data(), d.z.data(), out); }
  float height(double x, double y, double z) const;
  // Heights below the sea raised to it (a no-op without a sea).
  void raise_to_sea(int64_t n, float* h) const;
  // The sea's height, NaN without a sea.
  double sea_height() const { return sea_; }
  const PlanetConfig& config() const { return config_; }

 private:
  PlanetConfig config_;
  noise::SphereFbm fbm_;
  double sea_ = std::numeric_limits<double>::quiet_NaN();
};

// for_rows (core/parallel_rows.hpp) over h rows of w floats: row(y, out)
// writes row y's w floats.
void fill_rows(int32_t w, int32_t h, int threads, const Progress& progress,
               const std::function<void(int32_t, float*)>& row, float* data);

// Point i of the n-point Fibonacci sphere (equal areas, no poles favoured).
std::array<double, 3> fibonacci_point(int64_t i, int64_t n);

}  // namespace ft::planet
