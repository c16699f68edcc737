// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/polyline.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "polyline/classic_curves.hpp"
#include "polyline/ifs.hpp"
#include "polyline/lightning.hpp"
#include "polyline/polyline_checks.hpp"
#include "polyline/polyline_params.hpp"
#include "polyline/profile_curve.hpp"
#include "terrain/profile.hpp"

namespace ft::polyline {
namespace {

// Concatenates one curve per base segment (each from a to b) into one line;
// `count(depth)` gives the vertices of one segment's curve.
template <class Count, class Draw>
PolylineSet per_segment(const std::vector<Vec3>& base, int depth, double radius, Count count, Draw draw) {
  const int64_t per = count(depth);
  const int64_t total = 1 + int64_t(base.size() - 1) * (per - 1);
  check_allocation(checked_bytes(uint64_t(total), sizeof(Vec3) + sizeof(double)), "the polyline");
  PolylineSet s;
  s.points.resize(size_t(total));
  s.radii.assign(size_t(total), radius);
  for (size_t i = 0; i + 1 < base.size(); ++i) draw(base[i], base[i + 1], s.points.data() + int64_t(i) * (per - 1), i);
  s.end_line();
  return s;
}

// ifs.hpp's preset names carry the ABI's values, so ifs_preset passes through.
static_assert(int(kIfsFern) == FT_IFS_FERN && int(kIfsDragon) == FT_IFS_DRAGON && int(kIfsKoch) == FT_IFS_KOCH &&
              int(kIfsSierpinskiGasket) == FT_IFS_SIERPINSKI_GASKET);

}  // namespace

ft_polyline_params default_polyline_params() { return defaults_of<ft_polyline_params>(polyline_param_table()); }

std::vector<Vec3> base_points(const ft_polyline_params& p) {
  if (!p.base) return {{0, 0, 0}, {1, 0, 0}};
  std::vector<Vec3> v(size_t(p.base_count));
  for (size_t i = 0; i < v.size(); ++i) v[i] = {p.base[3 * i], p.base[3 * i + 1], p.base[3 * i + 2]};
  return v;
}

FplConfig fpl_config(const ft_polyline_params& p) {
  FplConfig c;
  c.rng = p.rng == FT_POLYLINE_RNG_NORMAL ? FplRng::kNormal : FplRng::kUniform;
  c.rule = p.method == FT_POLYLINE_DRAGON ? FplRule::kDragon : FplRule::kRandom;
  c.spread = p.spread;
  c.depth = p.depth;
  c.min_length = p.min_length;
  c.seed = p.seed;
  c.three_d = p.method == FT_POLYLINE_FPL3D;
  c.threads = p.threads;
  c.plane_normal = {p.plane_normal[0], p.plane_normal[1], p.plane_normal[2]};
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

void validate_polyline_params(const ft_polyline_params& p) {
  check_struct_size(p.struct_size, sizeof(ft_polyline_params), "ft_polyline_params");
  // The ranges of every field the method uses come from the table; what relates
  // fields to each other is in polyline_checks.cpp.
  check_ranges(polyline_param_table(), &p);
  check_polyline_cross_fields(p);
}

PolylineSet generate_polylines(const ft_polyline_params& p) {
  validate_polyline_params(p);
  const Progress progress(p.progress, p.progress_user);
  if (p.method == FT_POLYLINE_IFS) {
    std::vector<IfsMap> maps;
    if (p.ifs_table) {
      for (int32_t i = 0; i < p.ifs_maps; ++i) {
        const double* r = p.ifs_table + 7 * i;
        maps.push_back({r[0], r[1], r[2], r[3], r[4], r[5], r[6]});
      }
    } else {
      maps = ifs_preset(p.ifs_preset);
    }
    return ifs_points(maps, p.ifs_points, p.seed, progress);
  }
  const std::vector<Vec3> base = base_points(p);
  switch (p.method) {
    case FT_POLYLINE_KOCH:
      return per_segment(base, p.depth, p.radius, koch_vertex_count,
                         [&](const Vec3& a, const Vec3& b, Vec3* out, size_t) { koch_curve(a, b, p.depth, out); });
    case FT_POLYLINE_SIERPINSKI:
      return per_segment(base, p.depth, p.radius, arrowhead_vertex_count,
                         [&](const Vec3& a, const Vec3& b, Vec3* out, size_t) { arrowhead_curve(a, b, p.depth, out); });
    case FT_POLYLINE_PROFILE:
      return per_segment(base, p.depth, p.radius, profile_vertex_count,
                         [&](const Vec3& a, const Vec3& b, Vec3* out, size_t i) {
                           profile_curve(a, b, {p.depth, p.hurst, p.spread, p.seed}, i, out);
                         });
    default: {
      BranchConfig b;
      b.prob = p.branch_prob;
      b.decay = p.branch_decay;
      b.generations = p.branch_generations;
      b.radius = p.radius;
      return fpl_lightning(fpl_config(p), base, b);
    }
  }
}

}  // namespace ft::polyline
