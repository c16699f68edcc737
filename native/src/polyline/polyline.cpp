#include "polyline/polyline.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "polyline/classic_curves.hpp"
#include "polyline/ifs.hpp"
#include "polyline/lightning.hpp"
#include "polyline/profile_curve.hpp"
#include "terrain/profile.hpp"

namespace ft {
namespace {

std::string point_name(size_t i) { return "base point " + std::to_string(i + 1); }

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

ft_polyline_params default_polyline_params() {
  ft_polyline_params p{};
  p.struct_size = sizeof(ft_polyline_params);
  p.method = FT_POLYLINE_FPL;
  p.rng = FT_POLYLINE_RNG_UNIFORM;
  p.depth = 8;
  p.spread = 0.1;
  p.min_length = 0.0;
  p.seed = 1;
  p.base = nullptr;
  p.base_count = 0;
  p.branch_prob = 0.0;
  p.branch_decay = 0.5;
  p.branch_generations = 3;
  p.ifs_preset = FT_IFS_FERN;
  p.radius = 0.01;
  p.hurst = 0.8;
  p.ifs_table = nullptr;
  p.ifs_maps = 0;
  p.ifs_points = 100000;
  return p;
}

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
  check_int_range("method", p.method, FT_POLYLINE_FPL, FT_POLYLINE_PROFILE);
  check_int_range("threads", p.threads, 0, 1024);
  if (p.method == FT_POLYLINE_IFS) {
    if (p.ifs_table) {
      check_int_range("ifs_maps", p.ifs_maps, 1, 64);
    } else {
      check_int_range("ifs_preset", p.ifs_preset, FT_IFS_FERN, FT_IFS_SIERPINSKI_GASKET);
    }
    check_int_range("ifs_points", p.ifs_points, 1, int64_t(1) << 28);
    return;
  }
  // The base polyline.
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
  for (double v : p.plane_normal) check_finite("plane_normal", v);
  if (p.method == FT_POLYLINE_FPL3D &&
      (p.plane_normal[0] != 0 || p.plane_normal[1] != 0 || p.plane_normal[2] != 0)) {
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
  check_int_range("rng", p.rng, FT_POLYLINE_RNG_UNIFORM, FT_POLYLINE_RNG_NORMAL);
  if (!(p.spread >= 0) || !std::isfinite(p.spread))
    invalid("spread must be a finite number >= 0, got " + format_number(p.spread));
  if (!(p.min_length >= 0) || !std::isfinite(p.min_length))
    invalid("min_length must be a finite number >= 0, got " + format_number(p.min_length));
  if (!(p.radius >= 0) || !std::isfinite(p.radius))
    invalid("radius must be a finite number >= 0, got " + format_number(p.radius));
  check_range("branch_prob", p.branch_prob, 0.0, 1.0);
  if (!(p.branch_decay > 0 && p.branch_decay < 1))
    invalid("branch_decay must be in (0, 1), got " + format_number(p.branch_decay));
  check_int_range("branch_generations", p.branch_generations, 1, 8);
  switch (p.method) {
    case FT_POLYLINE_KOCH: check_int_range("depth", p.depth, 0, kMaxKochDepth); break;
    case FT_POLYLINE_SIERPINSKI: check_int_range("depth", p.depth, 0, kMaxArrowheadDepth); break;
    case FT_POLYLINE_PROFILE:
      check_int_range("depth", p.depth, 1, kMaxProfileLevels);
      check_range("hurst", p.hurst, 0.0, 1.0);
      check_positive("spread (the profile's sigma)", p.spread);
      break;
    default: check_int_range("depth", p.depth, 0, kMaxFplDepth);
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

}  // namespace ft
