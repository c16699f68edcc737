// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/fpl.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/parallel.hpp"
#include "core/rng.hpp"

namespace ft::polyline {
namespace {

constexpr uint32_t kAngleLevel = 64;  // Counter.level offset of the 3D angles
constexpr int kBlockLevels = 12;      // subtrees of 2^12 vertices (96 KiB) stay in L2
enum { kFlat = 0, kPlanar = 1, kRandom3d = 2 };  // displacement modes

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

  // Draws for n <= kChunk consecutive nodes from `first` into u (and the
  // angles into phi when needed): the same values as factor_at / angle_at.
  static constexpr size_t kChunk = 1024;
  void draws(int level, uint64_t first, size_t n, float* u, float* phi) const {
    if (c.rule != FplRule::kDragon) {
      const Counter k{line, uint32_t(level), Stream::kPolyline};
      if (c.rng == FplRng::kUniform) uniform_fill(c.seed, k, first, n, u);
      else gaussian_fill(c.seed, k, first, n, u);
    }
    if (needs_angle()) uniform_fill(c.seed, Counter{line, uint32_t(level) + kAngleLevel, Stream::kPolyline}, first, n, phi);
  }
  double factor_of(float draw, uint64_t j) const {
    return c.rule == FplRule::kDragon ? ((j & 1) ? -0.5 : 0.5) : factor(draw);
  }

  // d = c + f * (perpendicular of length |V|): the one formula both paths use.
  template <int kMode>
  Vec3 midpoint_as(const Vec3& a, const Vec3& b, double f, double phi) const {
    const Vec3 v{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const Vec3 m{a[0] + 0.5 * v[0], a[1] + 0.5 * v[1], a[2] + 0.5 * v[2]};
    if constexpr (kMode == kFlat) return {m[0] - f * v[1], m[1] + f * v[0], m[2]};  // Lrot(V) = [-Vy, Vx]
    const double len = norm(v);
    Vec3 dir;
    if constexpr (kMode == kPlanar) {
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
  int mode() const { return !c.three_d ? kFlat : planar3d ? kPlanar : kRandom3d; }
  Vec3 midpoint(const Vec3& a, const Vec3& b, double f, double phi) const {
    switch (mode()) {
      case kFlat: return midpoint_as<kFlat>(a, b, f, phi);
      case kPlanar: return midpoint_as<kPlanar>(a, b, f, phi);
      default: return midpoint_as<kRandom3d>(a, b, f, phi);
    }
  }
};

// Breadth-first refinement of levels [l0, l0 + nlev) of an array of
// 2^span + 1 vertices whose ends are set; its level-l0 node is `node0`.
// One instantiation per displacement mode keeps the inner loop branch-free.
template <int kMode>
void refine_as(const Engine& e, Vec3* out, int span, int l0, int nlev, uint64_t node0) {
  float u[Engine::kChunk], phi[Engine::kChunk];
  for (int k = 0; k < nlev; ++k) {
    const int64_t step = int64_t(1) << (span - k), half = step / 2;
    const size_t count = size_t(1) << k;
    const uint64_t first = node0 << k;
    for (size_t done = 0; done < count; done += Engine::kChunk) {
      const size_t n = std::min(Engine::kChunk, count - done);
      e.draws(l0 + k, first + done, n, u, phi);
      Vec3* p = out + int64_t(done) * step;
      for (size_t i = 0; i < n; ++i, p += step)
        p[half] = e.midpoint_as<kMode>(p[0], p[step], e.factor_of(u[i], first + done + i),
                                       kMode == kRandom3d ? 2.0 * std::numbers::pi * double(phi[i]) : 0.0);
    }
  }
}

void refine(const Engine& e, Vec3* out, int span, int l0, int nlev, uint64_t node0) {
  switch (e.mode()) {
    case kFlat: return refine_as<kFlat>(e, out, span, l0, nlev, node0);
    case kPlanar: return refine_as<kPlanar>(e, out, span, l0, nlev, node0);
    default: return refine_as<kRandom3d>(e, out, span, l0, nlev, node0);
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
  refine(e, out, depth, 0, top, 0);
  // Blocks are independent (draws keyed by position), so they run on any
  // number of threads with the same result; progress is reported between
  // groups of blocks, from the calling thread.
  const int64_t blocks = int64_t(1) << top;
  const int threads = resolve_threads(c.threads);
  constexpr int64_t kGroup = 64;
  for (int64_t g = 0; g < blocks; g += kGroup) {
    const int64_t end = std::min(blocks, g + kGroup);
#pragma omp parallel for num_threads(threads) schedule(static) if (end - g > 1 && threads > 1)
    for (int64_t t = g; t < end; ++t) refine(e, out + (t << sub), sub, top, sub, uint64_t(t));
    if (end < blocks) c.progress.report(double(end) / double(blocks));
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

}  // namespace ft::polyline
