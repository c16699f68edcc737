// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/profile_curve.hpp"

#include <vector>

#include "terrain/profile.hpp"

namespace ft::polyline {
namespace {

// A well-mixed seed per base segment (splitmix64's finaliser), so that the
// segments' profiles are independent while the polyline keeps one seed.
uint64_t segment_seed(uint64_t seed, uint64_t segment) {
  uint64_t x = seed ^ (segment * 0x9e3779b97f4a7c15ULL);
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  return x ^ (x >> 31);
}

}  // namespace

int64_t profile_vertex_count(int depth) { return (int64_t(1) << depth) + 1; }

void profile_curve(const Vec3& a, const Vec3& b, const ProfileCurve& c, uint64_t segment, Vec3* out) {
  const int64_t n = int64_t(1) << c.depth;
  std::vector<float> x(size_t(n) + 1);
  terrain::ProfileConfig pc;
  pc.levels = c.depth;
  pc.hurst = c.hurst;
  pc.sigma = c.sigma;
  pc.seed = segment_seed(c.seed, segment);
  terrain::midpoint_profile(pc, x.data());
  const double vx = b[0] - a[0], vy = b[1] - a[1], vz = b[2] - a[2];
  for (int64_t k = 0; k <= n; ++k) {
    const double t = double(k) / double(n);
    const double h = double(x[size_t(k)]) - double(x[0]) - t * (double(x[size_t(n)]) - double(x[0]));
    out[k] = {a[0] + t * vx - h * vy, a[1] + t * vy + h * vx, a[2] + t * vz};
  }
  out[0] = a;
  out[n] = b;
}

}  // namespace ft::polyline
