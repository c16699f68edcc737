// SPDX-License-Identifier: GPL-3.0-or-later
// A window's maps (landscape_window.hpp). Slope, curvature, water, eroded
// and deposited each read a sample and at most its four neighbours: the
// window grown by one ring gives the whole's bits. The drainage area is
// global (water that falls in one window runs through others): up to
// DrainageBlocks::whole_side it is computed on the whole eroded terrain,
// which the window's heights and ring are then read from (cheaper than
// eroding the window again); beyond, by the pieces the window touches
// (block_drainage.hpp), from the eroded terrain over their regions.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>

#include "erosion/block_drainage.hpp"
#include "erosion/landscape_window.hpp"
#include "erosion/sea.hpp"

namespace ft::erosion {
namespace {

// The whole's bands: at most this many samples each (the detail run's peak,
// about 72 bytes a sample, beside the whole's heights; each band is grown by
// the reach, so smaller bands cost more time), and their share of the bar.
constexpr int64_t kBandSamples = int64_t(1) << 23;
constexpr double kBandsShare = 0.6;

// The window's maps but the drainage area, from the window grown by one
// ring of the eroded terrain and of the terrain before (both read as g's
// samples, wrapping on a torus).
void ring_maps(const D8Grid& g, const HeightSource& eroded_src, const HeightSource& before_src, int64_t x0, int64_t y0,
               int32_t w, int32_t h, float* after, ErosionMaps& maps) {
  // The ring: inside a bounded grid (its edge is the whole's edge too, where
  // slope_curvature mirrors alike), wrapping on a torus (its positions kept
  // non-negative: the window's own start is at most the torus's side).
  auto grow = [&](int64_t lo, int32_t len, int32_t n, int64_t& first, int32_t& count) {
    int64_t a = lo - 1, b = lo + len + 1;
    if (!g.periodic) a = std::max<int64_t>(a, 0), b = std::min<int64_t>(b, n);
    if (a < 0) a += n, b += n;
    first = a, count = int32_t(b - a);
  };
  int64_t rx = 0, ry = 0;
  int32_t rw = 0, rh = 0;
  grow(x0, w, g.width, rx, rw);
  grow(y0, h, g.height, ry, rh);
  std::vector<float> before(size_t(rw) * rh), eroded(size_t(rw) * rh);
  eroded_src.read(rx, ry, rw, rh, eroded.data());
  before_src.read(rx, ry, rw, rh, before.data());
  // The ring's rectangle as a bounded grid of the whole's spacing: the
  // window's samples inside it see the whole's neighbours.
  D8Grid r;
  r.width = rw, r.height = rh, r.spacing = g.spacing;
  std::vector<float> slope(eroded.size()), curvature(eroded.size());
  slope_curvature(r, eroded.data(), slope.data(), curvature.data());
  // The whole's erode() by windows has no fluvial run (no uplift) and no
  // hydraulic pass (no water): erodes_by_windows.
  std::vector<float> lost(eroded.size()), laid(eroded.size());
  depth_maps(before.data(), eroded.data(), {}, int64_t(eroded.size()), lost.data(), laid.data());
  // The window's place in the ring: one sample in, but at a bounded grid's edge.
  const int32_t ox = g.periodic ? 1 : int32_t(x0 - rx), oy = g.periodic ? 1 : int32_t(y0 - ry);
  for (Heightfield* f : maps.all()) *f = Heightfield(w, h);
  for (int32_t j = 0; j < h; ++j) {
    const size_t from = size_t(oy + j) * rw + ox, to = size_t(j) * w;
    std::memcpy(after + to, eroded.data() + from, sizeof(float) * w);
    std::memcpy(maps.slope.data() + to, slope.data() + from, sizeof(float) * w);
    std::memcpy(maps.curvature.data() + to, curvature.data() + from, sizeof(float) * w);
    std::memcpy(maps.eroded.data() + to, lost.data() + from, sizeof(float) * w);
    std::memcpy(maps.deposited.data() + to, laid.data() + from, sizeof(float) * w);
    std::fill_n(maps.water_depth.data() + to, w, 0.0f);
  }
}

// A rectangle of g's samples in memory, [x0, x0 + w) x [y0, y0 + h)
// unwrapped, as a source of the samples it holds (on a torus at any copy).
class RectSource : public HeightSource {
 public:
  RectSource(const D8Grid& g, int64_t x0, int64_t y0, int32_t w, int32_t h, const float* z)
      : g_(g), x0_(x0), y0_(y0), w_(w), h_(h), z_(z) {}
  void read(int64_t x0, int64_t y0, int32_t w, int32_t h, float* out) const override {
    for (int32_t j = 0; j < h; ++j) {
      const int64_t y = offset(y0 + j, y0_, g_.height);
      for (int32_t i = 0; i < w; ++i) out[size_t(j) * w + i] = z_[size_t(y) * w_ + size_t(offset(x0 + i, x0_, g_.width))];
    }
  }

 private:
  int64_t offset(int64_t v, int64_t origin, int64_t n) const {
    return g_.periodic ? (((v - origin) % n) + n) % n : v - origin;
  }
  D8Grid g_;
  int64_t x0_, y0_;
  int32_t w_, h_;
  const float* z_;
};

// The whole's drainage area: the whole eroded terrain, by bands of whole
// rows (each the same bits as the whole's), and erode()'s sea: its cells are
// base levels of the flow.
void whole_window_maps(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, const D8Grid& grid,
                       int64_t x0, int64_t y0, int32_t w, int32_t h, float* after, ErosionMaps& maps) {
  D8Grid g = grid;
  std::vector<float> whole(g.size());
  std::vector<uint8_t> sea;
  if (!std::isnan(m.sea_level)) sea.resize(g.size());
  {
    const int64_t rows = std::max<int64_t>(64, kBandSamples / g.width);
    const int32_t bands = int32_t((g.height + rows - 1) / rows);
    std::vector<float> before;
    for (int32_t b = 0; b < bands; ++b) {
      const int32_t y = int32_t(int64_t(g.height) * b / bands), y1 = int32_t(int64_t(g.height) * (b + 1) / bands);
      const size_t first = size_t(y) * g.width, n = size_t(y1 - y) * g.width;
      before.resize(n);
      ErosionConfig bc = c;
      const ProgressPart part(c.progress, kBandsShare * b / bands, kBandsShare / bands);
      bc.progress = part.progress();
      erode_window(m, src, bc, 0, y, g.width, y1 - y, before.data(), whole.data() + first);
      for (size_t i = 0; !sea.empty() && i < n; ++i) sea[first + i] = in_sea(before[i], m.sea_level);
    }
  }
  ring_maps(g, ArraySource(g, whole.data()), src, x0, y0, w, h, after, maps);
  // The drainage area in place of the whole's heights (each read before it
  // is written), then the window's samples, wrapping on a torus.
  g.sea = sea.empty() ? nullptr : sea.data();
  {
    const ProgressPart part(c.progress, kBandsShare, 1.0 - kBandsShare);
    drainage_area_map(g, whole.data(), whole.data(), part.progress());
  }
  for (int32_t j = 0; j < h; ++j)
    for (int32_t i = 0; i < w; ++i)
      maps.drainage_area.data()[size_t(j) * w + i] =
          whole[size_t((y0 + j) % g.height) * g.width + size_t((x0 + i) % g.width)];
}

// The pieces' drainage area (block_drainage.hpp): the eroded terrain over
// the regions of the pieces the window touches, by bands of rows, then each
// piece from its region, its samples in the window kept.
void piece_window_maps(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, const D8Grid& g,
                       int64_t x0, int64_t y0, int32_t w, int32_t h, float* after, ErosionMaps& maps) {
  const CoarseFlow coarse = coarse_flow(m, src, g.spacing);
  // The pieces along each axis the window [lo, lo + len) touches, at the
  // copy it touches on a torus (it may run past the edge).
  struct Touched {
    PieceSpan canonical;
    int64_t lo;  // where the window meets it
  };
  auto touched = [&](int64_t lo, int32_t len, int32_t n) {
    std::vector<Touched> out;
    for (const int64_t shift : {int64_t(0), int64_t(n)})
      for (const PieceSpan& s : drainage_spans(n, g.periodic))
        if (s.lo + shift < lo + len && s.lo + shift + s.len > lo) out.push_back({s, s.lo + shift});
    return out;
  };
  const std::vector<Touched> tx = touched(x0, w, g.width), ty = touched(y0, h, g.height);
  // The union of their regions (the window and its ring inside it).
  int64_t ux0 = INT64_MAX, uy0 = INT64_MAX, ux1 = INT64_MIN, uy1 = INT64_MIN;
  for (const Touched& a : ty)
    for (const Touched& b : tx) {
      const PieceRect r = drainage_region(g, b.canonical, a.canonical);
      ux0 = std::min(ux0, r.x0 + b.lo - b.canonical.lo), ux1 = std::max(ux1, r.x0 + b.lo - b.canonical.lo + r.w);
      uy0 = std::min(uy0, r.y0 + a.lo - a.canonical.lo), uy1 = std::max(uy1, r.y0 + a.lo - a.canonical.lo + r.h);
    }
  const int32_t uw = int32_t(ux1 - ux0), uh = int32_t(uy1 - uy0);
  std::vector<float> before(size_t(uw) * uh), eroded(size_t(uw) * uh);
  {
    const int64_t rows = std::max<int64_t>(64, kBandSamples / uw);
    const int32_t bands = int32_t((uh + rows - 1) / rows);
    for (int32_t b = 0; b < bands; ++b) {
      const int32_t y = int32_t(int64_t(uh) * b / bands), y1 = int32_t(int64_t(uh) * (b + 1) / bands);
      ErosionConfig bc = c;
      const ProgressPart part(c.progress, kBandsShare * b / bands, kBandsShare / bands);
      bc.progress = part.progress();
      // (Positions kept non-negative on a torus: they wrap.)
      const int64_t ex = g.periodic && ux0 < 0 ? ux0 + g.width : ux0;
      const int64_t ey = g.periodic && uy0 + y < 0 ? uy0 + y + g.height : uy0 + y;
      erode_window(m, src, bc, ex, ey, uw, y1 - y, before.data() + size_t(y) * uw, eroded.data() + size_t(y) * uw);
    }
  }
  ring_maps(g, RectSource(g, ux0, uy0, uw, uh, eroded.data()), RectSource(g, ux0, uy0, uw, uh, before.data()), x0, y0,
            w, h, after, maps);
  // Each piece from its region's samples in the union, its own kept where the window has them.
  std::vector<float> rz, piece;
  std::vector<uint8_t> rsea;
  const bool has_sea = !std::isnan(m.sea_level);
  size_t done = 0;
  for (const Touched& a : ty)
    for (const Touched& b : tx) {
      const PieceRect region = drainage_region(g, b.canonical, a.canonical);
      const PieceRect p{b.canonical.lo, a.canonical.lo, b.canonical.len, a.canonical.len};
      const int64_t rx = region.x0 + b.lo - b.canonical.lo - ux0, ry = region.y0 + a.lo - a.canonical.lo - uy0;
      rz.resize(size_t(region.w) * region.h);
      rsea.assign(has_sea ? rz.size() : 0, 0);
      for (int32_t j = 0; j < region.h; ++j) {
        const size_t from = size_t(ry + j) * uw + size_t(rx), to = size_t(j) * region.w;
        std::copy_n(eroded.data() + from, region.w, rz.data() + to);
        for (int32_t i = 0; has_sea && i < region.w; ++i) rsea[to + i] = in_sea(before[from + i], m.sea_level);
      }
      piece.resize(size_t(p.w) * p.h);
      const double share = (1.0 - kBandsShare) / double(tx.size() * ty.size());
      const ProgressPart part(c.progress, kBandsShare + share * double(done++), share);
      piece_drainage_area(g, coarse, p, region, rz.data(), has_sea ? rsea.data() : nullptr, piece.data(),
                          part.progress());
      // The piece's samples inside the window.
      const int64_t px = b.lo, py = a.lo;
      for (int32_t j = 0; j < p.h; ++j) {
        const int64_t wy = py + j - y0;
        if (wy < 0 || wy >= h) continue;
        for (int32_t i = 0; i < p.w; ++i) {
          const int64_t wx = px + i - x0;
          if (wx >= 0 && wx < w) maps.drainage_area.data()[size_t(wy) * w + size_t(wx)] = piece[size_t(j) * p.w + i];
        }
      }
    }
}

}  // namespace

void erode_window_maps(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, double spacing,
                       int64_t x0, int64_t y0, int32_t w, int32_t h, float* after, ErosionMaps& maps) {
  D8Grid g = m.g;
  g.spacing = spacing;
  if (drains_by_blocks(g)) piece_window_maps(m, src, c, g, x0, y0, w, h, after, maps);
  else whole_window_maps(m, src, c, g, x0, y0, w, h, after, maps);
}

}  // namespace ft::erosion
