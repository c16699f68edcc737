// SPDX-License-Identifier: GPL-3.0-or-later
// A window's maps (landscape_window.hpp). Slope, curvature, water, eroded
// and deposited each read a sample and at most its four neighbours: the
// window grown by one ring gives the whole's bits. The drainage area is
// global (water that falls in one window runs through others): it is
// computed on the whole eroded terrain, which the window's heights and ring
// are then read from (cheaper than eroding the window again).
#include <algorithm>
#include <cmath>
#include <cstring>

#include "erosion/landscape_window.hpp"
#include "erosion/sea.hpp"

namespace ft::erosion {
namespace {

// The whole's bands: at most this many samples each (the detail run's peak,
// about 72 bytes a sample, beside the whole's heights; each band is grown by
// the reach, so smaller bands cost more time), and their share of the bar.
constexpr int64_t kBandSamples = int64_t(1) << 23;
constexpr double kBandsShare = 0.6;

}  // namespace

void erode_window_maps(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, double spacing,
                       int64_t x0, int64_t y0, int32_t w, int32_t h, float* after, ErosionMaps& maps) {
  // The whole eroded terrain, by bands of whole rows (each the same bits as
  // the whole's), and erode()'s sea: its cells are base levels of the flow.
  D8Grid g = m.g;
  g.spacing = spacing;
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
  ArraySource(g, whole.data()).read(rx, ry, rw, rh, eroded.data());
  src.read(rx, ry, rw, rh, before.data());
  // The ring's rectangle as a bounded grid of the whole's spacing: the
  // window's samples inside it see the whole's neighbours.
  D8Grid r;
  r.width = rw, r.height = rh, r.spacing = spacing;
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

}  // namespace ft::erosion
