// SPDX-License-Identifier: GPL-3.0-or-later
// Splat maps: weights that sum to exactly the total at every sample, the
// rules' thresholds, the rules JSON (its errors), RGBA files read back, and
// the CLI as a user runs it.
#include <gtest/gtest.h>
#include <omp.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "cli_run.hpp"
#include "progress_log.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"
#include "splat/rules_json.hpp"
#include "splat/splat_files.hpp"
#include "splat/splat_map.hpp"
#include "splat/splat_params.hpp"

namespace ft {
namespace {

namespace fs = std::filesystem;
using splat::band;

constexpr double kPi = 3.14159265358979323846;

ft_splat_params layer(const char* name) {
  ft_splat_params l = defaults_of<ft_splat_params>(splat::splat_param_table());
  l.name = name;
  return l;
}

// A plane rising along x at `degrees`, world size so that the spacing is 1.
Heightfield plane(int32_t n, double degrees) {
  Heightfield hf(n, n);
  hf.set_world_size(n - 1);
  for (int32_t y = 0; y < n; ++y)
    for (int32_t x = 0; x < n; ++x) hf.at(x, y) = float(x * std::tan(degrees * kPi / 180.0));
  return hf;
}

TEST(Splat, RoundingSumsToTheTotalAndStaysWithinOneOfTheExactShare) {
  // Random fractions of 1..8 layers (some zero), both totals: the sum is the
  // total exactly, and largest remainder puts each layer within 1 of its
  // exact share f x total (floor or floor + 1).
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (int32_t total : {255, 65535})
    for (int trial = 0; trial < 20000; ++trial) {
      const int32_t n = 1 + trial % 8;
      std::vector<float> f(static_cast<size_t>(n));
      double sum = 0;
      for (auto& v : f) sum += (v = u(rng) < 0.2 ? 0.0f : float(u(rng)));
      if (sum == 0) f[0] = 1, sum = 1;
      for (auto& v : f) v = float(v / sum);
      std::vector<uint16_t> q(static_cast<size_t>(n));
      splat::round_to_total(f.data(), n, total, q.data());
      int64_t s = 0;
      double fsum = 0;
      for (float v : f) fsum += v;
      for (int32_t k = 0; k < n; ++k) {
        s += q[size_t(k)];
        const double exact = f[size_t(k)] / fsum * total;
        EXPECT_GE(q[size_t(k)], std::floor(exact)) << trial;
        EXPECT_LE(q[size_t(k)], std::floor(exact) + 1) << trial;
      }
      ASSERT_EQ(s, total) << "trial " << trial << " with " << n << " layers";
    }
}

TEST(Splat, LargestRemainderByHand) {
  // Binary fractions, so that the shares are exact. 0.5, 0.25, 0.25 of 255:
  // 127.5, 63.75, 63.75 -> floors 127, 63, 63 (253); the two left go to the
  // largest remainders (0.75, 0.75): 127, 64, 64.
  const float f[] = {0.5f, 0.25f, 0.25f};
  uint16_t q[3];
  splat::round_to_total(f, 3, 255, q);
  EXPECT_EQ(q[0], 127);
  EXPECT_EQ(q[1], 64);
  EXPECT_EQ(q[2], 64);
  // 0.5, 0.5: 127.5 each, one left for a tie of remainders: the lower layer wins.
  const float half[] = {0.5f, 0.5f};
  splat::round_to_total(half, 2, 255, q);
  EXPECT_EQ(q[0], 128);
  EXPECT_EQ(q[1], 127);
  // 1/3 each of 65535 = 21845 exactly.
  const float t[] = {1 / 3.0f, 1 / 3.0f, 1 / 3.0f};
  splat::round_to_total(t, 3, 65535, q);
  EXPECT_EQ(q[0] + q[1] + q[2], 65535);
  EXPECT_EQ(q[0], 21845);
}

TEST(Splat, BandEdgesAndBlends) {
  EXPECT_EQ(band(0.5, 0.5, 1, 0), 1.0);              // a hard edge includes its end
  EXPECT_EQ(band(std::nextafter(0.5, 0.0), 0.5, 1, 0), 0.0);
  EXPECT_EQ(band(1.0, 0.5, 1, 0), 1.0);
  EXPECT_EQ(band(std::nextafter(1.0, 2.0), 0.5, 1, 0), 0.0);
  EXPECT_DOUBLE_EQ(band(0.5, 0.5, 1, 0.2), 0.5);     // half way at the edge itself
  EXPECT_NEAR(band(0.4, 0.5, 1, 0.2), 0.0, 1e-12);   // edge - blend / 2
  EXPECT_NEAR(band(0.6, 0.5, 1, 0.2), 1.0, 1e-12);   // edge + blend / 2
  EXPECT_NEAR(band(0.45, 0.5, 1, 0.2), 0.25, 1e-12);
  EXPECT_EQ(band(0.3, 0.5, 1, 0.2), 0.0);
  EXPECT_NEAR(band(0.95, 0.5, 1, 0.2), 0.75, 1e-12);  // the upper edge falls the same way
}

// The weight of layer 1 of {ground, rule} over a uniform terrain (the middle sample).
int weight_of_rule(const Heightfield& hf, const ft_splat_params& rule, const Heightfield* deposited = nullptr,
                   const Heightfield* area = nullptr) {
  const ft_splat_params layers[] = {layer("ground"), rule};
  const auto w = splat::splat_weights({&hf, deposited, area}, layers, 2, 255);
  const size_t mid = size_t(hf.height() / 2) * size_t(hf.width()) + size_t(hf.width() / 2);
  EXPECT_EQ(w[mid * 2] + w[mid * 2 + 1], 255);
  return w[mid * 2 + 1];
}

TEST(Splat, SlopeThresholdOnPlanesOfKnownSlope) {
  ft_splat_params rock = layer("rock");
  rock.slope_min = 30, rock.weight = 1000;  // where it holds, it all but takes the sample
  EXPECT_EQ(weight_of_rule(plane(9, 29.5), rock), 0);
  EXPECT_GE(weight_of_rule(plane(9, 30.5), rock), 254);
  rock.slope_blend = 10;  // half of the rule's weight at 30 degrees: 1000 x 0.5 against 1
  EXPECT_NEAR(weight_of_rule(plane(9, 30.0), rock), 255.0 * 500 / 501, 1.0);
  EXPECT_EQ(weight_of_rule(plane(9, 24.9), rock), 0);
}

TEST(Splat, HeightThresholdIsAFractionOfTheRange) {
  // Heights 0..1000 along x: the rule holds from 60 % of the range on.
  Heightfield hf(101, 5);
  for (int32_t y = 0; y < 5; ++y)
    for (int32_t x = 0; x < 101; ++x) hf.at(x, y) = float(10 * x);
  hf.set_world_size(1e6);  // flat enough that slope plays no part
  ft_splat_params snow = layer("snow");
  snow.height_min = 0.6, snow.weight = 1e3;
  const ft_splat_params layers[] = {layer("ground"), snow};
  const auto w = splat::splat_weights({&hf}, layers, 2, 255);
  for (int32_t x = 0; x < 101; ++x) {
    const size_t i = size_t(2 * 101 + x);
    EXPECT_EQ(w[i * 2 + 1] > 0, x >= 60) << x;
  }
}

TEST(Splat, SedimentTakesDepositOrFlow) {
  Heightfield hf = plane(9, 1), dep(9, 9), area(9, 9);
  const HeightStats s = hf.stats();
  ft_splat_params sed = layer("sediment");
  sed.deposit_min = 0.01, sed.flow_min = 0.1, sed.weight = 1000;
  for (size_t i = 0; i < dep.size(); ++i) dep.data()[i] = 0, area.data()[i] = 1e-3f;
  EXPECT_EQ(weight_of_rule(hf, sed, &dep, &area), 0);
  for (size_t i = 0; i < dep.size(); ++i) dep.data()[i] = float(0.02 * (s.max - s.min));
  EXPECT_GE(weight_of_rule(hf, sed, &dep, &area), 254) << "deposit above its threshold";
  for (size_t i = 0; i < dep.size(); ++i) dep.data()[i] = 0, area.data()[i] = float(0.2 * 8 * 8);
  EXPECT_GE(weight_of_rule(hf, sed, &dep, &area), 254) << "drainage area above 10 % of the map";
  EXPECT_EQ(weight_of_rule(hf, sed), 0) << "no maps: the conditions see 0";
}

TEST(Splat, WhereNoRuleHoldsTheFirstLayerTakesAll) {
  ft_splat_params a = layer("a"), b = layer("b");
  a.slope_min = 80, b.slope_min = 80;
  const Heightfield hf = plane(5, 10);
  const ft_splat_params layers[] = {a, b};
  const auto w = splat::splat_weights({&hf}, layers, 2, 65535);
  for (size_t i = 0; i < hf.size(); ++i) {
    EXPECT_EQ(w[2 * i], 65535);
    EXPECT_EQ(w[2 * i + 1], 0);
  }
}

TEST(Splat, DefaultRulesOnATerrainSumExactlyAndAreThreadFree) {
  // A valley side steepening uphill: 200 (x / 128)^2 over 500 world units
  // (slope 0 at x = 0, 39 degrees at the top) with ripples along y: grass
  // low down, rock on the steep upper part, snow on top where it is under 45
  // degrees.
  Heightfield hf(129, 97);
  hf.set_world_size(500);
  for (int32_t y = 0; y < 97; ++y)
    for (int32_t x = 0; x < 129; ++x) hf.at(x, y) = float(200 * (x / 128.0) * (x / 128.0) + 2 * std::sin(0.2 * y));
  const auto layers = splat::default_layers();
  const int32_t n = int32_t(layers.size());
  omp_set_num_threads(1);
  const auto one = splat::splat_weights({&hf}, layers.data(), n, 255);
  omp_set_num_threads(2);
  const auto two = splat::splat_weights({&hf}, layers.data(), n, 255);
  EXPECT_EQ(one, two);
  std::array<int64_t, 4> used{};
  for (size_t i = 0; i < hf.size(); ++i) {
    int s = 0;
    for (int32_t k = 0; k < n; ++k) s += one[i * size_t(n) + size_t(k)], used[size_t(k)] += one[i * size_t(n) + size_t(k)];
    ASSERT_EQ(s, 255) << "sample " << i;
  }
  EXPECT_GT(used[0], 0);  // grass low down
  EXPECT_GT(used[1], 0);  // rock on the steep sides
  EXPECT_GT(used[3], 0);  // snow on top
}

TEST(Splat, ColorsMixTheLayersColoursByTheirShares) {
  ft_splat_params red = layer("red"), blue = layer("blue");
  red.color[0] = 1, red.color[1] = 0, red.color[2] = 0, red.weight = 1;
  blue.color[0] = 0, blue.color[1] = 0, blue.color[2] = 1, blue.weight = 3;
  const Heightfield hf = plane(3, 0);
  const ft_splat_params layers[] = {red, blue};
  const auto rgb = splat::splat_colors({&hf}, layers, 2);
  EXPECT_NEAR(rgb[0], 0.25, 1e-6);
  EXPECT_NEAR(rgb[1], 0.0, 1e-6);
  EXPECT_NEAR(rgb[2], 0.75, 1e-6);
}

TEST(Splat, LinearRgbaIsTheLinearColoursRowByRowWithProgressAndCancel) {
  // Blender's colour attribute: the POV-Ray scenes' linear colours to the
  // bit, with alpha 1, on any thread count, over a valley side with deposits
  // and drainage areas (every default layer shows). One thread reports after
  // every row, rising to exactly 1; a cancel at half way ends the call with
  // nothing called back after it. (Seen to fail: with only the red channel
  // decoded, 25026 wrong values; with the progress not passed to the rows,
  // no report.)
  Heightfield hf(129, 97), deposited(129, 97), area(129, 97);
  hf.set_world_size(500);
  for (int32_t y = 0; y < 97; ++y)
    for (int32_t x = 0; x < 129; ++x) {
      hf.at(x, y) = float(200 * (x / 128.0) * (x / 128.0) + 2 * std::sin(0.2 * y));
      deposited.at(x, y) = float(std::max(0.0, std::sin(0.3 * x + 0.1 * y)));
      area.at(x, y) = float(std::pow(10.0, 6.0 * std::fabs(std::cos(0.05 * x * y))));
    }
  const splat::SplatInputs in{&hf, &deposited, &area};
  const auto layers = splat::default_layers();
  const int32_t n = int32_t(layers.size());
  const std::vector<float> linear = splat::splat_colors_linear(in, layers.data(), n);
  for (int threads : {1, 3}) {
    test::ProgressLog log;
    std::vector<float> rgba(hf.size() * 4, -1.0f);
    splat::splat_colors_linear_rgba(in, layers.data(), n, threads, Progress(&test::ProgressLog::call, &log),
                                    rgba.data());
    size_t wrong = 0;
    for (size_t i = 0; i < hf.size(); ++i) {
      for (int c = 0; c < 3; ++c) wrong += rgba[4 * i + size_t(c)] != linear[3 * i + size_t(c)];
      wrong += rgba[4 * i + 3] != 1.0f;
    }
    EXPECT_EQ(wrong, 0u) << threads << " threads";
    // One thread: a report after each of the 97 rows, then 1.
    test::expect_rises_to_one_in_small_steps(log, threads == 1 ? 98 : 1, threads == 1 ? 1.0 / 97 + 1e-12 : 1.0);
    if (threads == 1) EXPECT_EQ(log.seen.size(), 98u);
  }
  test::ProgressLog log;
  log.cancel_from = 0.5;
  std::vector<float> rgba(hf.size() * 4);
  try {
    splat::splat_colors_linear_rgba(in, layers.data(), n, 1, Progress(&test::ProgressLog::call, &log),
                                    rgba.data());
    ADD_FAILURE() << "not cancelled";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_CANCELLED);
  }
  ASSERT_GT(log.cancelled_at, 0u);
  EXPECT_EQ(log.seen.size(), log.cancelled_at);
  EXPECT_LT(log.seen.back(), 0.52);
}

TEST(SplatRules, DefaultsRoundTripThroughJson) {
  const auto d = splat::default_layers();
  const splat::SplatRules r = splat::parse_rules(splat::rules_to_json(d), "defaults");
  ASSERT_EQ(r.layers.size(), d.size());
  for (size_t k = 0; k < d.size(); ++k) {
    EXPECT_STREQ(r.layers[k].name, d[k].name);
    EXPECT_EQ(std::memcmp(&r.layers[k].height_min, &d[k].height_min,
                          sizeof(ft_splat_params) - offsetof(ft_splat_params, height_min)),
              0)
        << d[k].name;
  }
}

void expect_refused(const std::string& json, const std::string& words) {
  try {
    splat::parse_rules(json, "rules.json");
    ADD_FAILURE() << "accepted: " << json;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("rules.json"), std::string::npos) << e.what();
  }
}

TEST(SplatRules, BadRulesAreRefusedWithTheFieldNamed) {
  expect_refused(R"({"layers": [{"name": "rock", "slop_min": 30}]})", "unknown field 'slop_min'");
  expect_refused(R"({"layers": [{"name": "rock"}, {"name": "rock"}]})", "'rock' is used twice");
  expect_refused(R"({"layers": [{"slope_min": 30}]})", "needs a \"name\"");
  expect_refused(R"({"layers": [{"name": "a", "slope_min": "steep"}]})", "slope_min must be a number");
  expect_refused(R"({"layers": [{"name": "a", "slope_min": 95}]})", "slope_min");
  expect_refused(R"({"layers": [{"name": "a", "height_min": 0.8, "height_max": 0.2}]})", "above height_max");
  expect_refused(R"({"layers": [{"name": "a", "color": [1, 0]}]})", "array of 3 numbers");
  expect_refused(R"({"layer": []})", "unknown key 'layer'");
  expect_refused(R"({"layers": []})", "non-empty array");
  expect_refused(R"({"layers": [)", "not JSON");
}

class SplatFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("ft_splat_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(SplatFiles, SixLayersGoToTwoRgbaFilesThatSumToTheTotal) {
  const int32_t w = 7, h = 5, n = 6;
  std::vector<uint16_t> weights(size_t(w * h * n));
  std::mt19937 rng(3);
  for (size_t i = 0; i < size_t(w * h); ++i) {
    std::vector<float> f(n);
    float s = 0;
    for (auto& v : f) s += (v = float(rng() % 100));
    if (s == 0) f[0] = 1, s = 1;
    for (auto& v : f) v /= s;
    splat::round_to_total(f.data(), n, 65535, weights.data() + i * n);
  }
  const auto files = splat::write_splat_pngs(path("s.png"), weights, w, h, n, 16);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1].path, path("s_1.png"));
  EXPECT_EQ(files[1].layers, 2);
  const io::ChannelImage a = io::read_png_channels(files[0].path), b = io::read_png_channels(files[1].path);
  EXPECT_EQ(a.channels, 4);
  EXPECT_EQ(a.bit_depth, 16);
  for (size_t i = 0; i < size_t(w * h); ++i) {
    int64_t s = 0;
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(a.samples[i * 4 + c], weights[i * n + c]);
      s += a.samples[i * 4 + c] + b.samples[i * 4 + c];
    }
    EXPECT_EQ(b.samples[i * 4 + 2], 0);  // unused channels of the last file
    EXPECT_EQ(s, 65535);
  }
}

using test::CliRun;
using test::run_cli;

TEST_F(SplatFiles, CliWritesSplatAndColourFromAnErodedTerrain) {
  const std::string t = path("t.png"), e = path("e.png"), maps = path("maps");
  ASSERT_EQ(run_cli("terrain --method midpoint --levels 6 --seed 3 --out " + t).code, 0);
  ASSERT_EQ(run_cli("erode --in " + t + " --preset land --out " + e + " --maps " + maps).code, 0);
  const CliRun r = run_cli("splat --in " + e + " --maps " + maps + " --out " + path("s.png") + " --color " +
                           path("c.png"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["layers"].size(), 4u);
  EXPECT_EQ(j["layers"][2]["name"], "sediment");
  const io::ChannelImage s = io::read_png_channels(path("s.png"));
  ASSERT_EQ(s.width, 65);
  std::array<int64_t, 4> used{};
  for (size_t i = 0; i < size_t(s.width * s.height); ++i) {
    int sum = 0;
    for (int c = 0; c < 4; ++c) sum += s.samples[i * 4 + c], used[size_t(c)] += s.samples[i * 4 + c];
    ASSERT_EQ(sum, 255);
  }
  EXPECT_GT(used[2], 0) << "the eroded terrain's deposits and channels give sediment";
  EXPECT_EQ(io::read_png_channels(path("c.png")).channels, 3);
}

TEST_F(SplatFiles, CliRefusesBadRulesWithOneClearLine) {
  const std::string t = path("t.png");
  ASSERT_EQ(run_cli("terrain --method midpoint --levels 4 --out " + t).code, 0);
  io::write_file_atomically(path("r.json"), R"({"layers": [{"name": "a"}, {"name": "a"}]})");
  const CliRun r = run_cli("splat --in " + t + " --rules " + path("r.json") + " --out " + path("s.png"));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("used twice"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("s.png")));
}

// `fracterra scene` paints the terrain with the splat colour map by default:
// its colours PNG is `fracterra splat --color` of the same terrain, rules and
// maps (within 1 of 255: the scene's colours go sRGB -> linear float ->
// sRGB bytes, which can cross a rounding boundary), a rules file's single
// red layer makes it all red, and --texture altitude keeps ft_terrain.inc's.
// (Broken on purpose, the scene's colours without --maps' deposits and flow
// were off by 23 of 255 at the tenth value.)
TEST_F(SplatFiles, CliSceneIsColouredByTheSplatRules) {
  const std::string t = path("t.png"), e = path("e.png"), maps = path("maps");
  ASSERT_EQ(run_cli("terrain --method midpoint --levels 5 --seed 3 --out " + t).code, 0);
  ASSERT_EQ(run_cli("erode --in " + t + " --preset land --out " + e + " --maps " + maps).code, 0);
  ASSERT_EQ(run_cli("splat --in " + e + " --maps " + maps + " --color " + path("c.png")).code, 0);
  CliRun r = run_cli("scene --terrain " + e + " --maps " + maps + " --pov " + path("s.pov"));
  ASSERT_EQ(r.code, 0) << r.err;
  const io::ChannelImage want = io::read_png_channels(path("c.png")), got = io::read_png_channels(path("s.colors.png"));
  ASSERT_EQ(got.samples.size(), want.samples.size());
  size_t same = 0;
  for (size_t i = 0; i < got.samples.size(); ++i) {
    ASSERT_LE(std::abs(int(got.samples[i]) - int(want.samples[i])), 1) << "value " << i;
    same += got.samples[i] == want.samples[i];
  }
  EXPECT_GT(same, got.samples.size() * 9 / 10);
  const std::string sdl = io::read_file(path("s.pov"));
  EXPECT_NE(sdl.find("image_map { png \"s.colors.png\""), std::string::npos);

  io::write_file_atomically(path("red.json"), R"({"layers": [{"name": "red", "color": [1, 0, 0]}]})");
  r = run_cli("scene --terrain " + e + " --rules " + path("red.json") + " --pov " + path("red.pov"));
  ASSERT_EQ(r.code, 0) << r.err;
  const io::ChannelImage red = io::read_png_channels(path("red.colors.png"));
  for (size_t i = 0; i < red.samples.size(); i += 3)
    ASSERT_EQ((std::array<int, 3>{int(red.samples[i]), int(red.samples[i + 1]), int(red.samples[i + 2])}),
              (std::array<int, 3>{255, 0, 0}));

  r = run_cli("scene --terrain " + e + " --texture altitude --pov " + path("alt.pov"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_FALSE(fs::exists(path("alt.colors.png")));
  EXPECT_NE(io::read_file(path("alt.pov")).find("FT_Terrain_Texture("), std::string::npos);
  r = run_cli("scene --terrain " + e + " --texture altitude --rules " + path("red.json") + " --pov " + path("x.pov"));
  EXPECT_NE(r.code, 0);
  EXPECT_NE(r.err.find("--texture altitude"), std::string::npos) << r.err;
  // `fracterra terrain --pov` colours by the built-in rules too.
  ASSERT_EQ(run_cli("terrain --method midpoint --levels 4 --out " + path("u.png") + " --pov " + path("u.pov")).code, 0);
  EXPECT_TRUE(fs::exists(path("u.colors.png")));
}

}  // namespace
}  // namespace ft
