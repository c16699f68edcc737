#include "polyline/fpl.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/rng.hpp"

namespace ft {
namespace {

constexpr uint32_t kAngleLevel = 64;  // Counter.level offset of the 3D angles
constexpr int kBlockLevels = 12;      // subtrees of 2^12 vertices (96 KiB) stay in L2

inline double norm(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

inline Vec3 unit(const Vec3& v) {
  const double n = norm(v);
  return {v[0] / n, v[1] / n, v[2] / n};
}

inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The per-line constants of the displacement rule.
struct Engine {
  const FplConfig& c;
  uint32_t line;
  Vec3 normal{0, 0, 0};
  bool planar3d = false;

  Engine(const FplConfig& config, uint32_t line_id) : c(config), line(line_id) {
    if (c.three_d && norm(c.plane_normal) > 0) {
      normal = unit(c.plane_normal);
      planar3d = true;
    }
  }

  // rf(lambda) for node j of level l, from its uniform (0,1) or normal draw.
  double factor(float draw) const {
    return c.rng == FplRng::kUniform ? c.spread * (2.0 * double(draw) - 1.0) : c.spread * double(draw);
  }
  double factor_at(int level, uint64_t j) const {
    if (c.rule == FplRule::kDragon) return (j & 1) ? -0.5 : 0.5;
    const Counter k{line, uint32_t(level), Stream::kPolyline};
    return factor(c.rng == FplRng::kUniform ? bits_to_unit_open(random_bits(c.seed, k, j))
                                            : gaussian_at(c.seed, k, j));
  }
  double angle_at(int level, uint64_t j) const {
    const Counter k{line, uint32_t(level) + kAngleLevel, Stream::kPolyline};
    return 2.0 * std::numbers::pi * double(bits_to_unit_open(random_bits(c.seed, k, j)));
  }
  bool needs_angle() const { return c.three_d && !planar3d; }

  // Batch versions for n consecutive nodes from `first` (same values).
  void factors(int level, uint64_t first, size_t n, double* out) const {
    if (c.rule == FplRule::kDragon) {
      for (size_t i = 0; i < n; ++i) out[i] = ((first + i) & 1) ? -0.5 : 0.5;
      return;
    }
    float buf[1024];
    const Counter k{line, uint32_t(level), Stream::kPolyline};
    for (size_t done = 0; done < n;) {
      const size_t m = std::min<size_t>(n - done, 1024);
      if (c.rng == FplRng::kUniform) uniform_fill(c.seed, k, first + done, m, buf);
      else gaussian_fill(c.seed, k, first + done, m, buf);
      for (size_t i = 0; i < m; ++i) out[done + i] = factor(buf[i]);
      done += m;
    }
  }
  void angles(int level, uint64_t first, size_t n, double* out) const {
    float buf[1024];
    const Counter k{line, uint32_t(level) + kAngleLevel, Stream::kPolyline};
    for (size_t done = 0; done < n;) {
      const size_t m = std::min<size_t>(n - done, 1024);
      uniform_fill(c.seed, k, first + done, m, buf);
      for (size_t i = 0; i < m; ++i) out[done + i] = 2.0 * std::numbers::pi * double(buf[i]);
      done += m;
    }
  }

  // d = c + f * (perpendicular of length |V|): the one formula both paths use.
  Vec3 midpoint(const Vec3& a, const Vec3& b, double f, double phi) const {
    const Vec3 v{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const Vec3 m{a[0] + 0.5 * v[0], a[1] + 0.5 * v[1], a[2] + 0.5 * v[2]};
    if (!c.three_d) return {m[0] - f * v[1], m[1] + f * v[0], m[2]};  // Lrot(V) = [-Vy, Vx]
    const double len = norm(v);
    Vec3 dir;
    if (planar3d) {
      dir = unit(cross(normal, v));
    } else {
      // A basis perpendicular to V that depends on V only: e1 from the axis
      // least aligned with V.
      const double ax = std::fabs(v[0]), ay = std::fabs(v[1]), az = std::fabs(v[2]);
      const Vec3 axis = ax <= ay && ax <= az ? Vec3{1, 0, 0} : ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
      const Vec3 e1 = unit(cross(v, axis));
      const Vec3 e2 = cross(unit(v), e1);
      const double cs = std::cos(phi), sn = std::sin(phi);
      dir = {cs * e1[0] + sn * e2[0], cs * e1[1] + sn * e2[1], cs * e1[2] + sn * e2[2]};
    }
    const double s = f * len;
    return {m[0] + s * dir[0], m[1] + s * dir[1], m[2] + s * dir[2]};
  }
};

// Breadth-first refinement of levels [l0, l0 + nlev) of an array of
// 2^span + 1 vertices whose ends are set; its level-l0 node is `node0`.
void refine(const Engine& e, Vec3* out, int span, int l0, int nlev, uint64_t node0, double* f,
            double* phi) {
  for (int k = 0; k < nlev; ++k) {
    const int64_t step = int64_t(1) << (span - k), half = step / 2;
    const size_t count = size_t(1) << k;
    const uint64_t first = node0 << k;
    e.factors(l0 + k, first, count, f);
    if (e.needs_angle()) e.angles(l0 + k, first, count, phi);
    Vec3* p = out;
    for (size_t j = 0; j < count; ++j, p += step)
      p[half] = e.midpoint(p[0], p[step], f[j], e.needs_angle() ? phi[j] : 0.0);
  }
}

// The recursion as printed (depth-first), used when min_length > 0 because
// the shape of the tree then depends on the draws. out == nullptr counts.
struct Recursion {
  const Engine& e;
  Vec3* out;
  int64_t n = 0;
  int64_t limit;
  const FplSplitVisitor* visitor;
  int visit_levels;

  void run(const Vec3& a, const Vec3& b, int level, uint64_t j) {
    const Vec3 v{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    if (level == e.c.depth || norm(v) < e.c.min_length) {
      if (out) out[n] = b;
      if (++n > limit)
        fail(FT_ERR_TOO_LARGE, "the FPL has more than " + std::to_string(limit) +
                                   " vertices, above the memory cap (raise min_length or lower depth)");
      return;
    }
    const Vec3 d = e.midpoint(a, b, e.factor_at(level, j), e.needs_angle() ? e.angle_at(level, j) : 0.0);
    if (visitor && level < visit_levels) (*visitor)(level, j, a, b, d);
    run(a, d, level + 1, 2 * j);
    run(d, b, level + 1, 2 * j + 1);
  }
};

int64_t vertex_limit() { return int64_t(std::min<uint64_t>(memory_cap() / (sizeof(Vec3) + sizeof(double)), uint64_t(1) << 40)); }

}  // namespace

int64_t fpl_vertex_count(const FplConfig& c, const Vec3& a, const Vec3& b, uint32_t line_id) {
  check_int_range("depth", c.depth, 0, kMaxFplDepth);
  if (c.min_length <= 0) return (int64_t(1) << c.depth) + 1;
  const Engine e(c, line_id);
  Recursion r{e, nullptr, 1, vertex_limit(), nullptr, 0};
  r.run(a, b, 0, 0);
  return r.n;
}

void fpl_segment(const FplConfig& c, const Vec3& a, const Vec3& b, uint32_t line_id, Vec3* out,
                 const FplSplitVisitor* visitor, int visit_levels) {
  check_int_range("depth", c.depth, 0, kMaxFplDepth);
  const Engine e(c, line_id);
  out[0] = a;
  if (c.min_length > 0) {
    Recursion r{e, out, 1, vertex_limit(), visitor, visit_levels};
    r.run(a, b, 0, 0);
    return;
  }
  const int depth = c.depth;
  const int64_t n = int64_t(1) << depth;
  out[n] = b;
  // Levels above the blocks over the whole array, then each block of
  // 2^kBlockLevels vertices finished while it is in cache.
  const int top = std::max(0, depth - kBlockLevels);
  const int sub = depth - top;
  const size_t scratch = size_t(1) << std::max(top, sub);
  std::vector<double> f(scratch), phi(e.needs_angle() ? scratch : 0);
  refine(e, out, depth, 0, top, 0, f.data(), phi.data());
  const uint64_t blocks = uint64_t(1) << top;
  for (uint64_t t = 0; t < blocks; ++t) {
    refine(e, out + (int64_t(t) << sub), sub, top, sub, t, f.data(), phi.data());
    if ((t & 255) == 255) c.progress.report(double(t + 1) / double(blocks));
  }
  if (visitor) {
    // The splits, recovered from the finished array (nodes never move).
    for (int l = 0; l < std::min(depth, visit_levels); ++l) {
      const int64_t step = n >> l, half = step / 2;
      for (uint64_t j = 0; j < (uint64_t(1) << l); ++j) {
        const int64_t i0 = int64_t(j) * step;
        (*visitor)(l, j, out[i0], out[i0 + step], out[i0 + half]);
      }
    }
  }
}

}  // namespace ft
