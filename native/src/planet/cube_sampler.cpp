// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/cube_sampler.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/memory.hpp"
#include "planet/cube_sphere.hpp"

namespace ft::planet {

CubeSampler::CubeSampler(const MidpointConfig& c, int level, int threads, const Progress& progress)
    : level_(level), n_(int64_t(1) << level) {
  const int64_t side = n_ + 1;
  FaceRects rects;
  for (FaceRect& r : rects) r = {0, 0, n_, n_};
  check_allocation(checked_bytes(6 * uint64_t(side), uint64_t(side), sizeof(float)) +
                       midpoint_work_bytes(level, rects),
                   "a midpoint planet's cube-sphere of level " + std::to_string(level) + " (to interpolate)");
  std::array<float*, 6> out;
  for (int f = 0; f < 6; ++f) {
    faces_[size_t(f)].resize(size_t(side * side));
    out[size_t(f)] = faces_[size_t(f)].data();
  }
  midpoint_faces(c, level, rects, out, threads, progress);
}

float CubeSampler::height(double x, double y, double z) const {
  double s, t;
  const int f = face_of_direction(x, y, z, &s, &t);
  const double n = double(n_);
  const double u = std::clamp((s + 1.0) * 0.5 * n, 0.0, n), v = std::clamp((t + 1.0) * 0.5 * n, 0.0, n);
  const int64_t i = std::min<int64_t>(int64_t(u), n_ - 1), j = std::min<int64_t>(int64_t(v), n_ - 1);
  const double fu = u - double(i), fv = v - double(j);
  const float* a = faces_[size_t(f)].data() + j * (n_ + 1) + i;
  const float* b = a + (n_ + 1);
  const double top = a[0] + fu * (double(a[1]) - a[0]), bottom = b[0] + fu * (double(b[1]) - b[0]);
  return float(top + fv * (bottom - top));
}

int sampler_level_for(double radians) {
  int level = 1;
  while (2.0 / std::ldexp(1.0, level) > radians && level < kMaxLevel) ++level;
  return level;
}

}  // namespace ft::planet
