// SPDX-License-Identifier: GPL-3.0-or-later
// Marching squares in two passes: every cell writes its directed segments as
// links "crossing -> next crossing" (each crossing is the start of a segment
// in exactly one cell, so rows can run in parallel without races); then the
// links are followed serially in crossing order, border starts first, which
// makes the output independent of the thread count.
#include "contour/marching_squares.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

#include "core/error.hpp"
#include "core/memory.hpp"

namespace ft::contour {
namespace {

constexpr uint32_t kNone = 0xFFFFFFFFu;

class Tracer {
 public:
  Tracer(const Heightfield& hf, double level)
      : z_(hf.data()), w_(hf.width()), h_(hf.height()), level_(level),
        horizontal_(uint64_t(h_) * uint64_t(w_ - 1)) {
    const uint64_t edges = horizontal_ + uint64_t(h_ - 1) * uint64_t(w_);
    if (edges >= kNone)
      fail(FT_ERR_TOO_LARGE, "the heightfield has " + std::to_string(edges) +
                                 " cell edges; marching squares handles fewer than 2^32 (about 46000 x 46000 samples)");
    check_allocation(checked_bytes(edges, sizeof(uint32_t) + 2), "the contour links of a " + std::to_string(w_) +
                                                                      " x " + std::to_string(h_) + " heightfield");
    next_.assign(edges, kNone);
    incoming_.assign(edges, 0);
  }

  PolylineSet run() {
    link_cells();
    PolylineSet out;
    std::vector<uint8_t> used(next_.size(), 0);
    // Open chains start at a border crossing that nothing leads into.
    for (uint32_t e = 0; e < next_.size(); ++e)
      if (next_[e] != kNone && !incoming_[e]) trace(e, used, out, false);
    // What is left are closed loops.
    for (uint32_t e = 0; e < next_.size(); ++e)
      if (next_[e] != kNone && !used[e]) trace(e, used, out, true);
    return out;
  }

 private:
  bool land(int64_t x, int64_t y) const { return z_[y * w_ + x] >= level_; }
  uint32_t hedge(int64_t x, int64_t y) const { return uint32_t(y * (w_ - 1) + x); }
  uint32_t vedge(int64_t x, int64_t y) const { return uint32_t(horizontal_ + uint64_t(y * w_ + x)); }

  // Corners v0 (x, y), v1 (x+1, y), v2 (x+1, y+1), v3 (x, y+1) run
  // counter-clockwise; edge k joins corner k to corner k + 1. Walking the cell
  // boundary counter-clockwise, a crossing from land to water is an "exit"
  // and from water to land an "entry"; a segment from an exit to an entry
  // keeps the land on its left.
  void link_cells() {
#pragma omp parallel for schedule(dynamic, 16)
    for (int64_t y = 0; y < h_ - 1; ++y)
      for (int64_t x = 0; x < w_ - 1; ++x) {
        const bool c[4] = {land(x, y), land(x + 1, y), land(x + 1, y + 1), land(x, y + 1)};
        const int n = c[0] + c[1] + c[2] + c[3];
        if (n == 0 || n == 4) continue;
        const uint32_t edge[4] = {hedge(x, y), vedge(x + 1, y), hedge(x, y + 1), vedge(x, y)};
        // Saddle: join the land corners through the centre when the cell
        // mean is land (each exit goes to the next entry counter-clockwise),
        // else cut the land corners off (each exit goes to the previous entry).
        // With two crossings next and previous entry coincide.
        bool centre_land = true;
        if (n == 2 && c[0] == c[2]) {
          const int64_t i = y * w_ + x;
          const double mean = 0.25 * (double(z_[i]) + z_[i + 1] + z_[i + w_ + 1] + z_[i + w_]);
          centre_land = mean >= level_;
        }
        for (int k = 0; k < 4; ++k) {
          if (!(c[k] && !c[(k + 1) & 3])) continue;  // not an exit
          int m = k;
          do m = (m + (centre_land ? 1 : 3)) & 3;
          while (!(!c[m] && c[(m + 1) & 3]));         // until an entry
          next_[edge[k]] = edge[m];
          incoming_[edge[m]] = 1;
        }
      }
  }

  Vec3 crossing(uint32_t e) const {
    int64_t x0, y0, x1, y1;
    if (e < horizontal_) {
      y0 = y1 = e / (w_ - 1), x0 = e % (w_ - 1), x1 = x0 + 1;
    } else {
      const uint64_t v = e - horizontal_;
      y0 = int64_t(v) / w_, x0 = x1 = int64_t(v) % w_, y1 = y0 + 1;
    }
    const double a = z_[y0 * w_ + x0], b = z_[y1 * w_ + x1];
    const double t = (level_ - a) / (b - a);  // a and b straddle the level: b != a
    return {double(x0) + t * double(x1 - x0), double(y0) + t * double(y1 - y0), level_};
  }

  void trace(uint32_t start, std::vector<uint8_t>& used, PolylineSet& out, bool closed) {
    const int64_t first = out.vertex_count();
    auto add = [&](const Vec3& p) {
      // Samples exactly on the level put two crossings of a cell on the same
      // vertex: drop the repeat.
      if (out.vertex_count() > first && out.points.back() == p) return;
      out.add(p);
    };
    uint32_t e = start;
    while (e != kNone && !used[e]) {
      used[e] = 1;
      add(crossing(e));
      e = next_[e];
    }
    if (closed || e != kNone) add(crossing(start));
    // A loop or chain that collapsed onto one point carries no curve.
    const int64_t n = out.vertex_count() - first;
    if (n < 2 || (closed && n < 4)) {
      out.points.resize(size_t(first));
      out.radii.resize(size_t(first));
      return;
    }
    out.end_line();
  }

  const float* z_;
  int64_t w_, h_;
  double level_;
  uint64_t horizontal_;
  std::vector<uint32_t> next_;
  std::vector<uint8_t> incoming_;
};

}  // namespace

PolylineSet marching_squares(const Heightfield& hf, double level) {
  check_finite("level", level);
  if (hf.width() < 2 || hf.height() < 2)
    invalid("contouring needs a heightfield of at least 2 x 2 samples, got " + std::to_string(hf.width()) + " x " +
            std::to_string(hf.height()));
  const float* z = hf.data();
  for (size_t i = 0; i < hf.size(); ++i)
    if (!std::isfinite(z[i]))
      invalid("heightfield sample (x " + std::to_string(i % size_t(hf.width())) + ", y " +
              std::to_string(i / size_t(hf.width())) + ") is " + format_number(z[i]) +
              "; contouring needs finite samples (fill or clip no-data first)");
  return Tracer(hf, level).run();
}

double signed_area(const PolylineSet& set, int64_t i) {
  const int64_t b = set.line_begin(i), e = set.line_end(i);
  double a = 0;
  for (int64_t k = b; k < e; ++k) {
    const Vec3& p = set.points[size_t(k)];
    const Vec3& q = set.points[size_t(k + 1 < e ? k + 1 : b)];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * a;
}

ChainKind chain_kind(const PolylineSet& set, int64_t i) {
  const int64_t b = set.line_begin(i), e = set.line_end(i);
  if (e - b < 4 || set.points[size_t(b)] != set.points[size_t(e - 1)]) return ChainKind::kOpen;
  return signed_area(set, i) > 0 ? ChainKind::kIsland : ChainKind::kLake;
}

PolylineSet marching_squares(const Heightfield& hf, const std::vector<double>& levels) {
  PolylineSet all;
  for (double level : levels) {
    const PolylineSet one = marching_squares(hf, level);
    const int64_t base = all.vertex_count();
    all.points.insert(all.points.end(), one.points.begin(), one.points.end());
    all.radii.insert(all.radii.end(), one.radii.begin(), one.radii.end());
    for (size_t k = 1; k < one.offsets.size(); ++k) all.offsets.push_back(base + one.offsets[k]);
  }
  return all;
}

}  // namespace ft::contour
