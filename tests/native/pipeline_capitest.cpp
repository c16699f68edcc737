// SPDX-License-Identifier: GPL-3.0-or-later
// The terrain pipeline through the C ABI (fracterra/pipeline.h): the same
// bits as its stages called one by one, one erosion rule for tiling
// terrains (a torus of the true period, so the result still tiles), bad
// input refused before any work with a message, cancel, nothing leaked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fracterra/fracterra.h"

namespace {

struct Built {
  ft_heightfield* hf = nullptr;
  ft_heightfield* maps[FT_MAP_COUNT] = {};
  ~Built() {
    ft_heightfield_free(hf);
    for (auto* m : maps) ft_heightfield_free(m);
  }
  float at(int x, int y) const { return ft_heightfield_data(hf)[size_t(y) * ft_heightfield_width(hf) + x]; }
};

ft_terrain_params midpoint(bool periodic) {
  ft_terrain_params t;
  ft_terrain_params_init(&t);
  t.levels = 6;
  t.seed = 3;
  t.periodic = periodic;
  return t;
}

ft_terrain_params spectral() {
  ft_terrain_params t;
  ft_terrain_params_init(&t);
  t.method = FT_TERRAIN_SPECTRAL;
  t.width = 64, t.height = 48;
  t.seed = 3;
  return t;
}

ft_status build(const ft_terrain_params& t, int32_t preset, Built& out, bool maps = false,
                const ft_erosion_params* e = nullptr) {
  ft_build_params b;
  EXPECT_EQ(ft_build_params_init(&b), FT_OK);
  b.terrain = &t;
  b.erosion = e;
  b.erosion_preset = preset;
  b.threads = 2;
  return ft_terrain_build(&b, &out.hf, maps ? out.maps : nullptr);
}

std::vector<float> samples(const ft_heightfield* hf) {
  const float* z = ft_heightfield_data(hf);
  return {z, z + size_t(ft_heightfield_width(hf)) * ft_heightfield_height(hf)};
}

TEST(PipelineCapi, WithoutErosionItIsTheGeneratedTerrain) {
  const ft_terrain_params t = midpoint(true);
  Built b;
  ASSERT_EQ(build(t, FT_EROSION_PRESET_NONE, b), FT_OK) << ft_last_error();
  ft_heightfield* g = nullptr;
  ASSERT_EQ(ft_terrain_generate(&t, &g), FT_OK);
  EXPECT_EQ(samples(b.hf), samples(g));
  EXPECT_EQ(ft_heightfield_world_size(b.hf), ft_heightfield_world_size(g));
  ft_heightfield_free(g);
}

TEST(PipelineCapi, ABoundedTerrainErodesAsTheFittedPresetDoes) {
  // The stages one by one (what the CLI and the add-on assembled before):
  // generate, the preset fitted to the terrain, erode bounded.
  const ft_terrain_params t = midpoint(false);
  Built b;
  ASSERT_EQ(build(t, FT_EROSION_PRESET_VALLEYS, b, true), FT_OK) << ft_last_error();
  ft_heightfield* g = nullptr;
  ASSERT_EQ(ft_terrain_generate(&t, &g), FT_OK);
  ft_erosion_params e;
  ASSERT_EQ(ft_erosion_preset_fitted("valleys", g, &e), FT_OK);
  e.threads = 1;  // the bits never depend on it
  ft_heightfield* eroded = nullptr;
  ASSERT_EQ(ft_erode(g, &e, &eroded, nullptr), FT_OK);
  EXPECT_EQ(samples(b.hf), samples(eroded));
  for (auto* m : b.maps) ASSERT_NE(m, nullptr);
  ft_heightfield_free(g);
  ft_heightfield_free(eroded);
}

// The w x h samples from (0, 0) of a heightfield `stride` samples wide,
// shifted by (dx, dy) across the edges of their torus.
std::vector<float> rolled(const float* z, int stride, int w, int h, int dx, int dy) {
  std::vector<float> out(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out[size_t((y + dy) % h) * w + (x + dx) % w] = z[size_t(y) * stride + x];
  return out;
}

// Erosion saw the wrap when the built terrain is, sample for sample, what
// eroding its generated heights on a torus of `w` x `h` gives after a shift
// across the edges: on a torus there is no seam, so the shift commutes with
// erosion (Erosion.PeriodicTerrainsStaySeamless, whose tolerance this is; a
// bounded grid fails it, its edges are outlets). The worst difference.
double shifted_torus_difference(const ft_terrain_params& t, const Built& b, int w, int h) {
  ft_heightfield* g = nullptr;
  EXPECT_EQ(ft_terrain_generate(&t, &g), FT_OK);
  const int stride = ft_heightfield_width(g), dx = w / 3, dy = h / 2 + 1;
  ft_erosion_params e;
  EXPECT_EQ(ft_erosion_preset_fitted("land", g, &e), FT_OK);
  e.periodic = 1;
  const std::vector<float> shifted = rolled(ft_heightfield_data(g), stride, w, h, dx, dy);
  ft_heightfield* torus = nullptr;
  EXPECT_EQ(ft_heightfield_create(w, h, shifted.data(), &torus), FT_OK);
  // The same spacing as the whole grid's: world_size / (stride - 1).
  ft_heightfield_set_world_size(torus, ft_heightfield_world_size(g) * (w - 1) / (stride - 1));
  ft_heightfield* eroded = nullptr;
  EXPECT_EQ(ft_erode(torus, &e, &eroded, nullptr), FT_OK) << ft_last_error();
  const std::vector<float> want = rolled(ft_heightfield_data(b.hf), stride, w, h, dx, dy);
  const float* got = ft_heightfield_data(eroded);
  double worst = 0;
  for (size_t i = 0; i < want.size(); ++i) worst = std::max(worst, double(std::fabs(want[i] - got[i])));
  for (auto* hf : {g, torus, eroded}) ft_heightfield_free(hf);
  return worst;
}

TEST(PipelineCapi, AnErodedPeriodicMidpointTerrainStillTilesAndErosionSeesTheWrap) {
  Built periodic;
  ASSERT_EQ(build(midpoint(true), FT_EROSION_PRESET_LAND, periodic, true), FT_OK) << ft_last_error();
  const int n = ft_heightfield_width(periodic.hf);
  // The last row and column repeat the first, exactly, in the terrain and in every map.
  for (int k = 0; k < n; ++k) {
    ASSERT_EQ(periodic.at(n - 1, k), periodic.at(0, k)) << k;
    ASSERT_EQ(periodic.at(k, n - 1), periodic.at(k, 0)) << k;
  }
  for (auto* m : periodic.maps) {
    const float* z = ft_heightfield_data(m);
    for (int k = 0; k < n; ++k) ASSERT_EQ(z[size_t(k) * n + n - 1], z[size_t(k) * n]) << k;
  }
  // Its torus is 2^levels a side: the grid without its repeated last row and column.
  EXPECT_LE(shifted_torus_difference(midpoint(true), periodic, n - 1, n - 1), 1e-5);
}

TEST(PipelineCapi, AnErodedSpectralTerrainIsErodedOnItsTorusOfItsSize) {
  Built b;
  ASSERT_EQ(build(spectral(), FT_EROSION_PRESET_LAND, b), FT_OK) << ft_last_error();
  ASSERT_EQ(ft_heightfield_width(b.hf), 64);
  EXPECT_LE(shifted_torus_difference(spectral(), b, 64, 48), 1e-5);
}

TEST(PipelineCapi, BadInputIsRefusedBeforeAnyWorkWithAMessage) {
  ft_terrain_params t = midpoint(false);
  Built b;
  ft_build_params p;
  ASSERT_EQ(ft_build_params_init(&p), FT_OK);
  EXPECT_EQ(ft_terrain_build(&p, &b.hf, nullptr), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("terrain"), std::string::npos) << ft_last_error();
  EXPECT_EQ(b.hf, nullptr);
  EXPECT_EQ(build(t, 7, b), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("erosion_preset"), std::string::npos) << ft_last_error();
  ft_erosion_params e;
  ft_erosion_params_init(&e);
  e.evaporation = 2;
  EXPECT_EQ(build(t, FT_EROSION_PRESET_NONE, b, true, &e), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("evaporation"), std::string::npos) << ft_last_error();
  EXPECT_NE(std::string(ft_last_error()).find("[0, 1]"), std::string::npos) << ft_last_error();
  for (auto* m : b.maps) EXPECT_EQ(m, nullptr);
  t.hurst = 2;
  EXPECT_EQ(build(t, FT_EROSION_PRESET_VALLEYS, b), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("hurst"), std::string::npos) << ft_last_error();
  EXPECT_EQ(b.hf, nullptr);
}

TEST(PipelineCapi, OneProgressBarAcrossTheStagesCancelsAnywhere) {
  const ft_terrain_params t = midpoint(true);
  for (double stop_at : {0.1, 0.5, 0.9}) {
    struct State {
      double last = -1, stop_at;
      bool monotone = true;
    } s{-1, stop_at};
    ft_build_params p;
    ft_build_params_init(&p);
    p.terrain = &t;
    p.erosion_preset = FT_EROSION_PRESET_LAND;
    p.progress_user = &s;
    p.progress = [](void* user, double f) -> int32_t {
      auto* st = static_cast<State*>(user);
      st->monotone = st->monotone && f >= st->last && f <= 1.0;
      st->last = f;
      return f >= st->stop_at ? 1 : 0;
    };
    Built b;
    EXPECT_EQ(ft_terrain_build(&p, &b.hf, b.maps), FT_ERR_CANCELLED) << stop_at;
    EXPECT_TRUE(s.monotone) << stop_at;
    EXPECT_EQ(b.hf, nullptr);
    for (auto* m : b.maps) EXPECT_EQ(m, nullptr);
  }
}

// The rivers stage (ABI 2.20) follows the method table's tiling rule: a
// periodic midpoint terrain is a torus of 2^levels a side, so no river ends at
// an edge, some cross the seam as one continuous line, and the water mask is
// the torus's. Broken (rivers traced bounded, as `terrain --rivers` did for
// every method but spectral): the water mask is the whole grid's, 3 segments
// end at the edge and none crosses the seam; this failed.
struct Network {
  ft_river_network* net = nullptr;
  ~Network() { ft_river_network_free(net); }
};

ft_status build_rivers(const ft_terrain_params& t, Built& out, Network& net) {
  ft_build_params b;
  EXPECT_EQ(ft_build_params_init(&b), FT_OK);
  ft_hydrology_params h;
  EXPECT_EQ(ft_hydrology_params_init(&h), FT_OK);
  h.min_area = 0.5;
  b.terrain = &t;
  b.rivers = &h;
  b.erosion_preset = FT_EROSION_PRESET_VALLEYS;
  b.threads = 2;
  return ft_terrain_build_rivers(&b, &out.hf, nullptr, &net.net);
}

std::vector<ft_river_segment> segments_of(const ft_river_network* net) {
  std::vector<ft_river_segment> s(size_t(ft_river_network_segment_count(net)));
  EXPECT_EQ(ft_river_network_segments(net, s.data(), int32_t(s.size())), FT_OK);
  return s;
}

TEST(PipelineCapi, RiversOfATilingTerrainWrapAcrossItsSeam) {
  ft_terrain_params t = midpoint(true);
  t.levels = 7;
  Built b;
  Network net;
  ASSERT_EQ(build_rivers(t, b, net), FT_OK) << ft_last_error();
  const int n = ft_heightfield_width(b.hf);  // 129: the torus is 128 a side
  const double spacing = ft_heightfield_world_size(b.hf) / (n - 1), period = (n - 1) * spacing;
  int32_t gw = 0, gh = 0;
  ASSERT_EQ(ft_river_network_grid(net.net, &gw, &gh), FT_OK);
  EXPECT_EQ(gw, n - 1);
  EXPECT_EQ(gh, n - 1);
  std::vector<int32_t> mask(size_t(n - 1) * (n - 1));
  EXPECT_EQ(ft_river_network_water_mask(net.net, mask.data(), int64_t(mask.size())), FT_OK) << ft_last_error();
  const auto segs = segments_of(net.net);
  ASSERT_GT(segs.size(), 10u);
  for (const auto& s : segs) EXPECT_NE(s.end, FT_RIVER_EDGE) << "a torus has no edge";
  ft_polylines* lines = nullptr;
  ASSERT_EQ(ft_river_network_polylines(net.net, &lines), FT_OK);
  const double* xyz = ft_polylines_xyz(lines);
  bool crosses = false;
  for (const auto& s : segs)
    for (int64_t v = s.first_vertex + 1; v < s.first_vertex + s.vertex_count; ++v) {
      const double* a = xyz + 3 * (v - 1);
      const double* c = xyz + 3 * v;
      EXPECT_LT(std::hypot(c[0] - a[0], c[1] - a[1]), 2 * spacing) << "a jump: the river does not wrap";
      crosses |= c[0] < 0 || c[1] < 0 || c[0] >= period || c[1] >= period;
    }
  ft_polylines_free(lines);
  EXPECT_TRUE(crosses) << "no river crosses the seam";

  // The same terrain bounded: rivers leave at its edges.
  Built bb;
  Network bounded;
  ASSERT_EQ(build_rivers(midpoint(false), bb, bounded), FT_OK) << ft_last_error();
  const auto bsegs = segments_of(bounded.net);
  EXPECT_TRUE(std::any_of(bsegs.begin(), bsegs.end(), [](const auto& s) { return s.end == FT_RIVER_EDGE; }));
}

TEST(PipelineCapi, RiversAreBuiltOnlyWhenAskedAndBadSettingsAreRefused) {
  const ft_terrain_params t = midpoint(false);
  Built b;
  Network net;
  ft_build_params p;
  ASSERT_EQ(ft_build_params_init(&p), FT_OK);
  EXPECT_EQ(p.rivers, nullptr);
  ft_hydrology_params h;
  ASSERT_EQ(ft_hydrology_params_init(&h), FT_OK);
  h.width_exponent = -1;
  p.terrain = &t;
  p.rivers = &h;
  EXPECT_EQ(ft_terrain_build_rivers(&p, &b.hf, nullptr, &net.net), FT_ERR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(ft_last_error()).find("width_exponent"), std::string::npos) << ft_last_error();
  EXPECT_EQ(b.hf, nullptr);
  EXPECT_EQ(net.net, nullptr);
  // Without the rivers output the stage does not run (its settings are not read).
  EXPECT_EQ(ft_terrain_build(&p, &b.hf, nullptr), FT_OK) << ft_last_error();
}

// An island whose landform flattened a sea at height 0, eroded: its rivers'
// sea is the landform's. Erosion lays sediment on that floor (80% of it
// within 2e-4 of the relief, 95% within 5e-3); the sea level taking 1e-3 of
// the relief above it, about 87% of the flattened cells must be sea (bound
// 80%). With 1e-6 of the relief, 66% were (at the bare level and levels 8,
// 14%: rivers ran on
// across the sea floor into hundreds of lakes), and this failed.
TEST(PipelineCapi, AnErodedIslandsRiversEndInItsLandformsSea) {
  ft_terrain_params t = midpoint(false);
  t.levels = 7;
  t.seed = 4;
  t.sigma = 2;
  t.levelling = 1;
  t.height_offset = 4;
  t.falloff = FT_FALLOFF_RADIAL;
  t.falloff_width = 1;
  t.edge_level = -1.5;
  t.sea = FT_SEA_HEIGHT;
  t.sea_level = 0;
  ft_heightfield* g = nullptr;
  ASSERT_EQ(ft_terrain_generate(&t, &g), FT_OK) << ft_last_error();
  const std::vector<float> flat = samples(g);
  ft_heightfield_free(g);
  Built b;
  Network net;
  ASSERT_EQ(build_rivers(t, b, net), FT_OK) << ft_last_error();
  std::vector<int32_t> mask(flat.size());
  ASSERT_EQ(ft_river_network_water_mask(net.net, mask.data(), int64_t(mask.size())), FT_OK) << ft_last_error();
  size_t sea = 0, flattened = 0, flattened_sea = 0;
  for (size_t i = 0; i < flat.size(); ++i) {
    sea += mask[i] == -2;
    flattened += flat[i] <= 0.0f;
    flattened_sea += flat[i] <= 0.0f && mask[i] == -2;
  }
  ASSERT_GT(flattened, flat.size() / 4) << "an island in a sea";
  EXPECT_GE(double(flattened_sea), 0.8 * double(flattened)) << sea << " sea cells";
  for (const auto& s : segments_of(net.net)) EXPECT_NE(s.end, FT_RIVER_EDGE);
}

}  // namespace
