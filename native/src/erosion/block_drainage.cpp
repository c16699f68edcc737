// SPDX-License-Identifier: GPL-3.0-or-later
// The drainage area by pieces (see block_drainage.hpp).
#include "erosion/block_drainage.hpp"

#include <algorithm>
#include <cmath>

#include "erosion/erosion.hpp"
#include "erosion/multiple_flow.hpp"

namespace ft::erosion {
namespace {

DrainageBlocks g_blocks;

int64_t wrap_index(int64_t v, int64_t n) { return ((v % n) + n) % n; }

// How far along the ring the water of a coarse link looks for where it
// enters, in coarse cells either side of the inside cell's node: a coarse
// valley's water is spread over two or three cells by multiple flow.
constexpr double kSnapCells = 1.5;
// Links that carry at least this many coarse cells' area are rivers: the
// edge beside where they enter is walled (below).
// (At 1025^2 with a halo of 12 model cells, 16 left 13% of the channels
// of 10^4 cells or more off by over 2x, 4 left 5%; walling every inflow, 21%.)
constexpr double kRiverCells = 4.0;

// Each coarse link from a cell outside the region's interior (off its edge
// ring) into one inside: fn(given, along) with `along` the sides it crosses
// (one, or two for a diagonal link from a corner: 0..3 the region's left,
// right, top and bottom edge) and the whole's positions along each side
// [centre - half, centre + half] within kSnapCells coarse cells of the
// inside cell's node.
struct Side {
  int side;
  double centre, half;
};
// (At most two: a small vector without the heap.)
struct Along {
  Side s[2];
  int n = 0;
  void push_back(const Side& v) { s[n++] = v; }
  const Side* begin() const { return s; }
  const Side* end() const { return s + n; }
};

template <class Fn>
void for_each_inflow(const D8Grid& g, const CoarseFlow& f, const PieceRect& region, Fn&& fn) {
  if (region.w < 3 || region.h < 3) return;
  const double ix0 = double(region.x0 + 1), ix1 = double(region.x0 + region.w - 2);
  const double iy0 = double(region.y0 + 1), iy1 = double(region.y0 + region.h - 2);
  const double cx_mid = region.x0 + 0.5 * region.w, cy_mid = region.y0 + 0.5 * region.h;
  const D8Grid& c = f.g;
  for (int32_t by = 0; by < c.height; ++by) {
    double fy = by / f.to_y;
    if (g.periodic) fy += g.height * std::round((cy_mid - fy) / g.height);
    if (fy < iy0 || fy > iy1) continue;
    for (int32_t bx = 0; bx < c.width; ++bx) {
      double fx = bx / f.to_x;
      if (g.periodic) fx += g.width * std::round((cx_mid - fx) / g.width);
      if (fx < ix0 || fx > ix1) continue;
      for (int k = 0; k < 8; ++k) {
        // a, whose link k leads to b.
        int32_t ax = bx - kDx[k], ay = by - kDy[k];
        if (c.periodic) {
          ax = int32_t(wrap_index(ax, c.width)), ay = int32_t(wrap_index(ay, c.height));
        } else if (ax < 0 || ay < 0 || ax >= c.width || ay >= c.height) {
          continue;
        }
        const double given = f.given[size_t(ay) * c.width + ax][k];
        if (!(given > 0)) continue;
        const double fax = fx - kDx[k] / f.to_x, fay = fy - kDy[k] / f.to_y;
        Along along;
        if (fax < ix0 || fax > ix1) along.push_back({fax < ix0 ? 0 : 1, fy, kSnapCells / f.to_y});
        if (fay < iy0 || fay > iy1) along.push_back({fay < iy0 ? 2 : 3, fx, kSnapCells / f.to_x});
        fn(given, along);
      }
    }
  }
}

// Region-local cells of side `side` at ring `ring` (0: the edge, 1: the
// first ring inside) for the whole's positions [centre - half, centre + half]
// along it, inside the interior's span: fn(cell).
template <class Fn>
void for_each_along(const PieceRect& region, int side, int32_t ring, double centre, double half, Fn&& fn) {
  const bool column = side < 2;
  const int32_t at = side == 0 ? ring : side == 1 ? region.w - 1 - ring : side == 2 ? ring : region.h - 1 - ring;
  const int64_t origin = column ? region.y0 : region.x0;
  const int32_t len = column ? region.h : region.w;
  const int64_t lo = std::max<int64_t>(origin + 1, int64_t(std::ceil(centre - half)));
  const int64_t hi = std::min<int64_t>(origin + len - 2, int64_t(std::floor(centre + half)));
  for (int64_t v = lo; v <= hi; ++v) {
    const int32_t local = int32_t(v - origin);
    fn(column ? local * region.w + at : at * region.w + local);
  }
}

// The water the coarse grid sends into `region` (cells of the filled and
// graded surface z): each link's at the lowest cell of the first ring along
// it that drains only inwards (multiple_flow_area's receivers: lower cells,
// and on a flat the level ones of lower key, none on the edge), else the
// lowest: water put beside an edge cell it drains to would leave at once.
Inflow coarse_inflow(const D8Grid& g, const CoarseFlow& f, const PieceRect& region, const float* z,
                     const FlatGrading& flats) {
  auto inward = [&](int32_t i) {
    const int32_t x = i % region.w, y = i / region.w;
    bool gives = false;
    for (int k = 0; k < 8; ++k) {
      const int32_t nx = x + kDx[k], ny = y + kDy[k];
      const int32_t j = ny * region.w + nx;
      const bool receives = z[j] < z[i] || (flats.flat_cells > 0 && z[j] == z[i] && (flats.level[size_t(i)] >> k & 1u) &&
                                            flats.key[size_t(i)] > 0 && flats.key[size_t(j)] < flats.key[size_t(i)]);
      if (!receives) continue;
      if (nx == 0 || ny == 0 || nx == region.w - 1 || ny == region.h - 1) return false;
      gives = true;
    }
    return gives;
  };
  Inflow in;
  for_each_inflow(g, f, region, [&](double given, const Along& along) {
    int32_t best = -1;
    bool best_inward = false;
    for (const Side& a : along)
      for_each_along(region, a.side, 1, a.centre, a.half, [&](int32_t i) {
        const bool inw = inward(i);
        if (best < 0 || (inw && !best_inward) || (inw == best_inward && z[i] < z[best])) best = i, best_inward = inw;
      });
    if (best >= 0) in.emplace_back(best, given);
  });
  return in;
}

// The edge cells beside where a river enters, raised to the region's
// highest: the region's edge is an outlet, but where a river comes in, its
// bed just inside is often below the edge cells (a reach the whole's fill
// floods), and the river's water ran straight back out there.
void wall_river_entries(const D8Grid& g, const CoarseFlow& f, const PieceRect& region, float* z) {
  const double river = kRiverCells / (f.to_x * f.to_y) * g.spacing * g.spacing;
  std::vector<int32_t> walls;
  for_each_inflow(g, f, region, [&](double given, const Along& along) {
    if (given < river) return;
    for (const Side& a : along) for_each_along(region, a.side, 0, a.centre, a.half, [&](int32_t i) { walls.push_back(i); });
  });
  if (walls.empty()) return;
  const float top = *std::max_element(z, z + size_t(region.w) * region.h);
  for (const int32_t i : walls) z[i] = top;
}

}  // namespace

const DrainageBlocks& drainage_blocks() { return g_blocks; }
void set_drainage_blocks(const DrainageBlocks& b) { g_blocks = b; }

std::vector<PieceSpan> drainage_spans(int32_t n, bool periodic) {
  const int64_t b = g_blocks.block;
  std::vector<int64_t> lines;
  // No line closer than half a block to the far edge: the last block takes
  // the rest (8193 samples: lines at 2048, 4096, 6144, the last block 2048).
  for (int64_t l = periodic ? 0 : b; periodic ? l <= n - b / 2 : l <= n - 1 - b / 2; l += b) lines.push_back(l);
  std::vector<PieceSpan> out;
  int64_t start = 0;
  for (const int64_t l : lines) {
    if (l > start) out.push_back({start, int32_t(l - start)});
    out.push_back({l, 1});
    start = l + 1;
  }
  if (n > start) out.push_back({start, int32_t(n - start)});
  return out;
}

bool drains_by_blocks(const D8Grid& g) {
  if (std::max(g.width, g.height) <= g_blocks.whole_side) return false;
  if (!g.periodic) return true;
  for (const int32_t n : {g.width, g.height})
    for (const PieceSpan& s : drainage_spans(n, true))
      if (int64_t(s.len) + 2 * int64_t(g_blocks.halo) >= n) return false;
  return true;
}

PieceRect drainage_region(const D8Grid& g, const PieceSpan& x, const PieceSpan& y) {
  const int64_t hl = g_blocks.halo;
  auto grow = [&](const PieceSpan& s, int32_t n, int64_t& lo, int32_t& len) {
    int64_t a = s.lo - hl, b = s.lo + s.len + hl;
    if (!g.periodic) a = std::max<int64_t>(a, 0), b = std::min<int64_t>(b, n);
    lo = a, len = int32_t(b - a);
  };
  PieceRect r;
  grow(x, g.width, r.x0, r.w);
  grow(y, g.height, r.y0, r.h);
  return r;
}

CoarseFlow coarse_flow(const LandscapeModel& m, const HeightSource& eroded, double spacing) {
  LandscapeModel own;
  const LandscapeModel* from = &m;
  std::vector<float> z;
  if (m.coarse_to_fine) {
    z.resize(m.before.size());
    for (size_t i = 0; i < z.size(); ++i) z[i] = m.before[i] + m.change[i];
  } else {
    // No model's run on a coarser grid: the eroded terrain's own box means.
    D8Grid g = m.g;
    g.spacing = spacing;
    coarse_input(g, eroded, m.sea_level, own);
    from = &own;
    z = own.before;
  }
  const int32_t edge = m.g.periodic ? 0 : 1;
  CoarseFlow f;
  f.g = from->coarse;
  f.g.sea = nullptr;
  f.g.spacing = spacing * double(m.g.width - edge) / (f.g.width - edge);
  f.to_x = double(f.g.width - edge) / (m.g.width - edge);
  f.to_y = double(f.g.height - edge) / (m.g.height - edge);
  D8Grid cg = f.g;
  cg.sea = from->coarse_sea.empty() ? nullptr : from->coarse_sea.data();
  DrainageSurface s = drainage_surface(cg, z.data());
  std::vector<double> area;
  multiple_flow_area(cg, s.z.data(), s.sink, area, Progress(), &s.flats);
  f.given = multiple_flow_given(cg, s.z.data(), s.sink, &s.flats, area);
  return f;
}

void piece_drainage_area(const D8Grid& g, const CoarseFlow& f, const PieceRect& piece, const PieceRect& region,
                         const float* z, const uint8_t* sea, float* out, const Progress& progress) {
  D8Grid r;
  r.width = region.w, r.height = region.h;
  r.spacing = g.spacing;
  r.sea = sea;
  std::vector<float> walled(z, z + r.size());
  wall_river_entries(g, f, region, walled.data());
  DrainageSurface s;
  {
    // The flats' numbers of the whole's positions: pieces sharing a flat grade it alike.
    FlatFrame frame;
    frame.whole = g, frame.whole.sea = nullptr;
    frame.x0 = region.x0, frame.y0 = region.y0;
    const ProgressPart part(progress, 0.0, 0.5);
    s = drainage_surface(r, walled.data(), part.progress(), &frame);
  }
  const Inflow in = coarse_inflow(g, f, region, s.z.data(), s.flats);
  std::vector<double> area;
  {
    const ProgressPart part(progress, 0.5, 0.5);
    multiple_flow_area(r, s.z.data(), -1, area, part.progress(), &s.flats, &in);
  }
  const int64_t ox = piece.x0 - region.x0, oy = piece.y0 - region.y0;
  for (int32_t j = 0; j < piece.h; ++j)
    for (int32_t i = 0; i < piece.w; ++i)
      out[size_t(j) * piece.w + i] = float(area[size_t(oy + j) * region.w + size_t(ox + i)]);
}

void block_drainage_area(const D8Grid& g, const CoarseFlow& f, const float* z, float* area_out,
                         const Progress& progress) {
  const std::vector<PieceSpan> xs = drainage_spans(g.width, g.periodic), ys = drainage_spans(g.height, g.periodic);
  const double total = double(g.size());
  double done = 0;
  std::vector<float> rz, piece;
  std::vector<uint8_t> rsea;
  for (const PieceSpan& sy : ys)
    for (const PieceSpan& sx : xs) {
      const PieceRect region = drainage_region(g, sx, sy);
      const PieceRect p{sx.lo, sy.lo, sx.len, sy.len};
      rz.resize(size_t(region.w) * region.h);
      rsea.assign(g.sea ? rz.size() : 0, 0);
      for (int32_t j = 0; j < region.h; ++j) {
        const size_t row = size_t(wrap_index(region.y0 + j, g.height)) * g.width;
        for (int32_t i = 0; i < region.w; ++i) {
          const size_t from = row + size_t(wrap_index(region.x0 + i, g.width)), to = size_t(j) * region.w + i;
          rz[to] = z[from];
          if (g.sea) rsea[to] = g.sea[from];
        }
      }
      piece.resize(size_t(p.w) * p.h);
      const double share = double(p.w) * p.h / total;
      const ProgressPart part(progress, done, share);
      piece_drainage_area(g, f, p, region, rz.data(), g.sea ? rsea.data() : nullptr, piece.data(), part.progress());
      done += share;
      for (int32_t j = 0; j < p.h; ++j)
        std::copy_n(piece.data() + size_t(j) * p.w, p.w, area_out + size_t(p.y0 + j) * g.width + size_t(p.x0));
    }
  progress.report(1.0);
}

}  // namespace ft::erosion
