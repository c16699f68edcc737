// SPDX-License-Identifier: GPL-3.0-or-later
// The profile method of the polylines: Voss's 1D midpoint displacement
// (Voss 1988; seed 000) drawn across a base segment a -> b. The profile's
// linear trend is removed so both nodes survive exactly; its heights, in
// units of |ab|, displace the points to the left of ab in the x,y plane,
// and z is interpolated linearly between a and b.
#pragma once

#include <cstdint>

#include "core/polyline_set.hpp"

namespace ft::polyline {

struct ProfileCurve {
  int depth = 10;      // 2^depth segments
  double hurst = 0.8;  // H of the profile
  double sigma = 0.1;  // the profile's vertical scale, in units of |ab|
  uint64_t seed = 1;   // of the whole polyline; each segment's profile gets its own
};

// 2^depth + 1.
int64_t profile_vertex_count(int depth);

// Writes segment `segment`'s curve (including a and b) into out, which holds
// profile_vertex_count(c.depth) entries.
void profile_curve(const Vec3& a, const Vec3& b, const ProfileCurve& c, uint64_t segment, Vec3* out);

}  // namespace ft::polyline
