// SPDX-License-Identifier: GPL-3.0-or-later
// A midpoint planet's heights between its cube-sphere samples: the six
// faces at one level, bilinearly interpolated in the face's (s, t) (the
// gnomonic coordinates of the direction). For the layouts that are not the
// cube's own samples: the equirectangular map, the icosphere, the sea's
// quantile. Continuous across edges (the edge samples are shared bit for bit
// and an edge's interpolation reads only them).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "planet/midpoint_sphere.hpp"

namespace ft::planet {

class CubeSampler {
 public:
  // Checks the memory (6 (2^level + 1)^2 floats and the work) first.
  CubeSampler(const MidpointConfig& c, int level, int threads, const Progress& progress);
  float height(double x, double y, double z) const;
  int level() const { return level_; }

 private:
  int level_;
  int64_t n_;
  std::array<std::vector<float>, 6> faces_;
};

// The coarsest level whose spacing (2 / 2^level radians at a face's centre,
// the widest) is at most `radians`, at least 1; the caller's memory check
// refuses what is too fine.
int sampler_level_for(double radians);

}  // namespace ft::planet
