// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/ifs.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/rng.hpp"

namespace ft::polyline {

std::vector<IfsMap> ifs_preset(int preset) {
  switch (preset) {
    case kIfsFern:
      return {{0.0, 0.0, 0.0, 0.16, 0.0, 0.0, 0.01},
              {0.85, 0.04, -0.04, 0.85, 0.0, 1.6, 0.85},
              {0.2, -0.26, 0.23, 0.22, 0.0, 1.6, 0.07},
              {-0.15, 0.28, 0.26, 0.24, 0.0, 0.44, 0.07}};
    case kIfsDragon:  // seed 002: X' = -0.5X - 0.5Y + 490, Y' = 0.5X - 0.5Y + 120, ...
      return {{-0.5, -0.5, 0.5, -0.5, 490.0, 120.0, 0.5}, {0.5, -0.5, 0.5, 0.5, 340.0, -110.0, 0.5}};
    case kIfsKoch:    // seed 002, the four maps of its fig. 9
      return {{0.333, 0.0, 0.0, 0.333, 13.333, 200.0, 0.25},
              {0.333, 0.0, 0.0, 0.333, 413.333, 200.0, 0.25},
              {0.167, 0.289, -0.289, 0.167, 130.0, 256.0, 0.25},
              {0.167, -0.289, 0.289, 0.167, 403.0, 71.0, 0.25}};
    case kIfsSierpinskiGasket: {
      // seed 002: cut the central triangle out of each triangle, for ever;
      // what is left is three copies of the whole at ratio 1/2, each fixed
      // at one corner of the triangle (0, 0), (1, 0), (1/2, sqrt(3)/2).
      const double h = std::sqrt(3.0) / 4.0;  // half the triangle's height
      return {{0.5, 0.0, 0.0, 0.5, 0.0, 0.0, 1.0 / 3.0},
              {0.5, 0.0, 0.0, 0.5, 0.5, 0.0, 1.0 / 3.0},
              {0.5, 0.0, 0.0, 0.5, 0.25, h, 1.0 / 3.0}};
    }
    default:
      invalid("ifs_preset must be FT_IFS_FERN (0), FT_IFS_DRAGON (1), FT_IFS_KOCH (2) or "
              "FT_IFS_SIERPINSKI_GASKET (3), got " +
              std::to_string(preset));
  }
}

void validate_ifs(const std::vector<IfsMap>& maps) {
  check_int_range("ifs_maps", int64_t(maps.size()), 1, 64);
  double sum = 0;
  for (size_t i = 0; i < maps.size(); ++i) {
    const IfsMap& m = maps[i];
    for (double v : {m.a, m.b, m.c, m.d, m.e, m.f, m.p})
      if (!std::isfinite(v)) invalid("IFS map " + std::to_string(i) + " has a non-finite coefficient");
    if (m.p < 0) invalid("IFS map " + std::to_string(i) + " has probability " + format_number(m.p) + "; p must be >= 0");
    sum += m.p;
  }
  if (!(sum > 0)) invalid("the IFS probabilities must have a positive sum");
}

PolylineSet ifs_points(const std::vector<IfsMap>& maps, int64_t count, uint64_t seed, const Progress& progress) {
  validate_ifs(maps);
  check_int_range("ifs_points", count, 1, int64_t(1) << 28);
  check_allocation(checked_bytes(uint64_t(count), sizeof(Vec3) + sizeof(double) + sizeof(int64_t)), "the IFS points");
  std::vector<double> cumulative;
  double sum = 0;
  for (const IfsMap& m : maps) cumulative.push_back(sum += m.p);
  for (double& c : cumulative) c /= sum;
  cumulative.back() = 2.0;  // every draw in (0, 1) finds a map

  constexpr int64_t kDiscard = 64;
  PolylineSet s;
  s.points.resize(size_t(count));
  s.radii.assign(size_t(count), 0.0);
  s.offsets.resize(size_t(count) + 1);
  double x = 0, y = 0;
  float u[4096];
  const Counter k{0, 0, Stream::kIfs};
  const int64_t total = count + kDiscard;
  for (int64_t first = 0; first < total; first += 4096) {
    const int64_t m = std::min<int64_t>(4096, total - first);
    uniform_fill(seed, k, uint64_t(first), size_t(m), u);
    for (int64_t i = 0; i < m; ++i) {
      size_t j = 0;
      while (double(u[i]) >= cumulative[j]) ++j;
      const IfsMap& f = maps[j];
      const double nx = f.a * x + f.b * y + f.e, ny = f.c * x + f.d * y + f.f;
      x = nx, y = ny;
      const int64_t n = first + i - kDiscard;
      if (n >= 0) s.points[size_t(n)] = {x, y, 0.0};
    }
    if (!std::isfinite(x) || !std::isfinite(y))
      invalid("the IFS orbit diverges: its maps must be contractive (|det| < 1, singular values < 1)");
    if ((first & 0xfffff) == 0) progress.report(double(first) / double(total));
  }
  for (int64_t i = 0; i <= count; ++i) s.offsets[size_t(i)] = i;
  return s;
}

}  // namespace ft::polyline
