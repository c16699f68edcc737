// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/lightning.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <tuple>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "core/rng.hpp"

namespace ft::polyline {
namespace {

struct Fork {
  int generation;      // of the branch to make
  uint64_t parent_key; // seed of the parent line's draws
  uint32_t parent_line;
  int level;
  uint64_t node;
  Vec3 a, b, d;
  double radius;       // start radius of the branch
};

uint64_t splitmix(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

uint64_t branch_key(const Fork& f) {
  return splitmix(splitmix(splitmix(f.parent_key ^ f.parent_line) ^ uint64_t(f.level)) ^ f.node);
}

Vec3 rotate(const Vec3& v, const Vec3& axis, double angle) {  // Rodrigues, axis unit
  const double c = std::cos(angle), s = std::sin(angle);
  const double k = (axis[0] * v[0] + axis[1] * v[1] + axis[2] * v[2]) * (1 - c);
  const Vec3 x{axis[1] * v[2] - axis[2] * v[1], axis[2] * v[0] - axis[0] * v[2], axis[0] * v[1] - axis[1] * v[0]};
  return {v[0] * c + x[0] * s + axis[0] * k, v[1] * c + x[1] * s + axis[1] * k, v[2] * c + x[2] * s + axis[2] * k};
}

// Tapers the radii of vertices [begin, end) from r0 to r0 * decay.
void taper(PolylineSet& s, int64_t begin, int64_t end, double r0, double decay) {
  const double n = double(std::max<int64_t>(end - begin - 1, 1));
  for (int64_t i = begin; i < end; ++i)
    s.radii[size_t(i)] = r0 * (1.0 - (1.0 - decay) * double(i - begin) / n);
}

class Builder {
 public:
  Builder(const FplConfig& c, const BranchConfig& b) : c_(c), b_(b) {}

  PolylineSet run(const std::vector<Vec3>& base) {
    // Main line: exact size first (2^r per segment, or counted when delta > 0).
    std::vector<int64_t> counts(base.size() - 1);
    int64_t total = 1;
    for (size_t i = 0; i + 1 < base.size(); ++i) {
      counts[i] = fpl_vertex_count(c_, base[i], base[i + 1], uint32_t(i));
      total += counts[i] - 1;
    }
    reserve(total, "the FPL main line");
    const size_t start = set_.points.size();
    set_.points.resize(start + size_t(total));
    set_.radii.assign(set_.points.size(), b_.radius);
    int64_t off = int64_t(start);
    for (size_t i = 0; i + 1 < base.size(); ++i) {
      FplConfig ci = c_;
      ci.progress = Progress();  // one report per segment below instead
      emit_line(ci, base[i], base[i + 1], uint32_t(i), 1, b_.radius, set_.points.data() + off);
      off += counts[i] - 1;
      c_.progress.report(double(i + 1) / double(base.size() - 1));
    }
    set_.end_line();
    if (b_.prob > 0) taper(set_, 0, total, b_.radius, b_.decay);
    grow_branches();
    return std::move(set_);
  }

 private:
  void reserve(int64_t vertices, const char* what) {
    check_allocation(checked_bytes(uint64_t(set_.points.size() + size_t(vertices)), sizeof(Vec3) + sizeof(double)),
                     what);
  }

  // Fills one line's FPL and records its accepted forks.
  void emit_line(const FplConfig& ci, const Vec3& a, const Vec3& b, uint32_t line, int generation, double radius,
                 Vec3* out) {
    if (b_.prob <= 0 || generation > b_.generations) {
      fpl_segment(ci, a, b, line, out);
      return;
    }
    const uint64_t key = ci.seed;
    const double child_radius = radius * b_.decay;
    FplSplitVisitor visit = [&](int level, uint64_t node, const Vec3& pa, const Vec3& pb, const Vec3& d) {
      const Counter k{line, uint32_t(level), Stream::kPolylineBranch};
      if (double(bits_to_unit_open(random_bits(key, k, 4 * node))) < b_.prob * std::exp2(-0.5 * level))
        forks_.push_back({generation, key, line, level, node, pa, pb, d, child_radius});
    };
    fpl_segment(ci, a, b, line, out, &visit, ci.depth - 1);
  }

  void grow_branches() {
    // Forks in a stable order, then generation by generation (a branch's
    // forks join the next round).
    while (!forks_.empty()) {
      std::vector<Fork> round;
      round.swap(forks_);
      std::sort(round.begin(), round.end(), [](const Fork& x, const Fork& y) {
        return std::tie(x.generation, x.parent_key, x.parent_line, x.level, x.node) <
               std::tie(y.generation, y.parent_key, y.parent_line, y.level, y.node);
      });
      for (const Fork& f : round) make_branch(f);
    }
  }

  void make_branch(const Fork& f) {
    const Counter k{f.parent_line, uint32_t(f.level), Stream::kPolylineBranch};
    const double u1 = bits_to_unit_open(random_bits(f.parent_key, k, 4 * f.node + 1));
    const double u2 = bits_to_unit_open(random_bits(f.parent_key, k, 4 * f.node + 2));
    const double u3 = bits_to_unit_open(random_bits(f.parent_key, k, 4 * f.node + 3));
    const double angle = (20.0 + 25.0 * u1) * std::numbers::pi / 180.0 * (u2 < 0.5 ? -1.0 : 1.0);
    const Vec3 ab{f.b[0] - f.a[0], f.b[1] - f.a[1], f.b[2] - f.a[2]};
    const Vec3 db{f.b[0] - f.d[0], f.b[1] - f.d[1], f.b[2] - f.d[2]};
    const double ndb = norm(db);
    if (!(ndb > 0)) return;
    const Vec3 dir{db[0] / ndb, db[1] / ndb, db[2] / ndb};
    Vec3 axis{0, 0, 1};
    if (c_.three_d) {
      if (norm(c_.plane_normal) > 0) {
        const double n = norm(c_.plane_normal);
        axis = {c_.plane_normal[0] / n, c_.plane_normal[1] / n, c_.plane_normal[2] / n};
      } else {
        // A random axis perpendicular to the direction.
        const Vec3 helper = std::fabs(dir[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
        Vec3 e1{dir[1] * helper[2] - dir[2] * helper[1], dir[2] * helper[0] - dir[0] * helper[2],
                dir[0] * helper[1] - dir[1] * helper[0]};
        const double n1 = norm(e1);
        e1 = {e1[0] / n1, e1[1] / n1, e1[2] / n1};
        axis = rotate(e1, dir, 2.0 * std::numbers::pi * u3);
      }
    }
    const Vec3 bd = rotate(dir, axis, angle);
    const double len = b_.decay * norm(ab);
    const Vec3 end{f.d[0] + len * bd[0], f.d[1] + len * bd[1], f.d[2] + len * bd[2]};
    FplConfig cb = c_;
    cb.progress = Progress();
    cb.depth = std::max(1, c_.depth - f.level - 1);
    cb.seed = branch_key(f);
    const int64_t n = fpl_vertex_count(cb, f.d, end, 0);
    reserve(n, "the lightning branches");
    const int64_t begin = set_.vertex_count();
    set_.points.resize(size_t(begin + n));
    set_.radii.resize(size_t(begin + n));
    emit_line(cb, f.d, end, 0, f.generation + 1, f.radius, set_.points.data() + begin);
    set_.end_line();
    taper(set_, begin, begin + n, f.radius, b_.decay);
  }

  FplConfig c_;
  BranchConfig b_;
  PolylineSet set_;
  std::vector<Fork> forks_;
};

}  // namespace

PolylineSet fpl_lightning(const FplConfig& c, const std::vector<Vec3>& base, const BranchConfig& b) {
  if (base.size() < 2) invalid("an FPL needs at least 2 base points, got " + std::to_string(base.size()));
  return Builder(c, b).run(base);
}

}  // namespace ft::polyline
