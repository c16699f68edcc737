// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/polyline_checks.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "polyline/classic_curves.hpp"
#include "polyline/polyline.hpp"
#include "terrain/profile.hpp"

namespace ft::polyline {
namespace {

std::string point_name(size_t i) { return "base point " + std::to_string(i + 1); }

void check_base(const ft_polyline_params& p) {
  if (p.base) {
    if (p.base_count < 2)
      invalid("the base polyline needs at least 2 points, got " + std::to_string(p.base_count));
    check_int_range("base_count", p.base_count, 2, int64_t(1) << 30);
    const std::vector<Vec3> b = base_points(p);
    for (size_t i = 0; i < b.size(); ++i) {
      for (double v : b[i])
        if (!std::isfinite(v)) invalid(point_name(i) + " has a non-finite coordinate (NaN or infinity)");
      if (i > 0 && b[i] == b[i - 1])
        invalid(point_name(i) + " coincides with " + point_name(i - 1) +
                "; consecutive base points must differ (a zero-length segment has no direction)");
    }
  } else if (p.base_count != 0) {
    invalid("base is NULL but base_count is " + std::to_string(p.base_count) + " (NULL means the unit segment, count 0)");
  }
}

// FPL 3D in a plane: no base segment may be parallel to its normal.
void check_plane(const ft_polyline_params& p) {
  if (p.method != FT_POLYLINE_FPL3D || (p.plane_normal[0] == 0 && p.plane_normal[1] == 0 && p.plane_normal[2] == 0))
    return;
  const Vec3 n{p.plane_normal[0], p.plane_normal[1], p.plane_normal[2]};
  const std::vector<Vec3> b = base_points(p);
  for (size_t i = 1; i < b.size(); ++i) {
    const Vec3 v{b[i][0] - b[i - 1][0], b[i][1] - b[i - 1][1], b[i][2] - b[i - 1][2]};
    const Vec3 x{n[1] * v[2] - n[2] * v[1], n[2] * v[0] - n[0] * v[2], n[0] * v[1] - n[1] * v[0]};
    const double nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double vv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) <= 1e-9 * nn * vv)
      invalid("base segment " + std::to_string(i) + " is parallel to plane_normal, so no "
              "displacement direction is defined (unit(n x V)); the normal must not be parallel to a base segment");
  }
}

}  // namespace

void check_polyline_cross_fields(const ft_polyline_params& p) {
  if (p.method == FT_POLYLINE_IFS) {
    if (p.ifs_table) check_int_range("ifs_maps", p.ifs_maps, 1, 64);
    return;
  }
  check_base(p);
  check_plane(p);
  // The depth's range depends on the method (the table holds the widest, FPL's).
  switch (p.method) {
    case FT_POLYLINE_KOCH: check_int_range("depth", p.depth, 0, kMaxKochDepth); break;
    case FT_POLYLINE_SIERPINSKI: check_int_range("depth", p.depth, 0, kMaxArrowheadDepth); break;
    case FT_POLYLINE_PROFILE:
      check_int_range("depth", p.depth, 1, terrain::kMaxProfileLevels);
      check_positive("spread (the profile's sigma)", p.spread);
      break;
    default: break;
  }
  if (p.method != FT_POLYLINE_FPL && p.method != FT_POLYLINE_FPL3D && p.branch_prob > 0)
    invalid("branch_prob applies to the fpl and fpl3d methods only");
  // Sizes known in advance are checked before anything is made.
  if (p.min_length == 0 || p.method == FT_POLYLINE_KOCH || p.method == FT_POLYLINE_SIERPINSKI ||
      p.method == FT_POLYLINE_PROFILE) {
    const uint64_t segments = p.base ? uint64_t(p.base_count - 1) : 1;
    const double per = p.method == FT_POLYLINE_KOCH ? std::pow(4.0, p.depth)
                       : p.method == FT_POLYLINE_SIERPINSKI ? std::pow(3.0, p.depth)
                                                            : std::ldexp(1.0, p.depth);
    const double bytes = (double(segments) * per + 1) * double(sizeof(Vec3) + sizeof(double));
    check_allocation(bytes >= 1.8e19 ? UINT64_MAX : uint64_t(bytes), "a polyline of depth " + std::to_string(p.depth));
  }
}

}  // namespace ft::polyline
