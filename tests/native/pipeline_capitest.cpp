// The terrain pipeline through the C ABI (fracterra/pipeline.h): the same
// bits as its stages called one by one, one erosion rule for tiling
// terrains (a torus of the true period, so the result still tiles), bad
// input refused before any work with a message, cancel, nothing leaked.
#include <gtest/gtest.h>

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

// Sum of |difference| between neighbours across the wrap (the last column
// to the first of the next period) and, for comparison, across the grid's
// interior columns, per pair.
void seam_and_interior(const Built& b, int period_w, double* seam, double* interior) {
  const int h = ft_heightfield_height(b.hf);
  double s = 0, in = 0;
  for (int y = 0; y < h; ++y) {
    s += std::fabs(b.at(period_w - 1, y) - b.at(0, y));
    for (int x = 0; x + 1 < period_w; ++x) in += std::fabs(b.at(x + 1, y) - b.at(x, y));
  }
  *seam = s / h;
  *interior = in / (double(h) * (period_w - 1));
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
  // Erosion saw the wrap: eroded as a bounded grid, the edges are outlets
  // pinned near the lowest input height and the seam becomes a step;
  // eroded on its torus the step across the seam is an ordinary neighbour
  // difference. Measured (seed 3, levels 6): seam / interior = 1.0 on the
  // torus; a seam twice the interior's mean difference would be a wall.
  double seam = 0, interior = 0;
  seam_and_interior(periodic, n - 1, &seam, &interior);
  EXPECT_LT(seam, 2 * interior) << "seam " << seam << ", interior " << interior;
}

TEST(PipelineCapi, AnErodedSpectralTerrainStaysSeamlessWithPeriodItsSize) {
  Built b;
  ASSERT_EQ(build(spectral(), FT_EROSION_PRESET_LAND, b), FT_OK) << ft_last_error();
  ASSERT_EQ(ft_heightfield_width(b.hf), 64);
  double seam = 0, interior = 0;
  seam_and_interior(b, 64, &seam, &interior);
  EXPECT_LT(seam, 2 * interior) << "seam " << seam << ", interior " << interior;
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

}  // namespace
