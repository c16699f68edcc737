// SPDX-License-Identifier: GPL-3.0-or-later
// Splat rules files through the C ABI, as the add-on reads them: the layers
// `fracterra splat --rules` would use, their names alive until the handle
// goes, and bad files refused with the file, layer and field named.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "fracterra/fracterra.h"

namespace fs = std::filesystem;

namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const fs::path p = fs::temp_directory_path() / ("ft_splat_capi_" + std::to_string(::getpid()) + "_" + name);
  std::ofstream(p) << text;
  return p.string();
}

std::vector<ft_splat_params> layers_of(const ft_splat_rules* rules) {
  int32_t n = 0;
  EXPECT_EQ(ft_splat_rules_layers(rules, nullptr, 0, &n), FT_OK) << ft_last_error();
  std::vector<ft_splat_params> layers(static_cast<size_t>(n));
  for (auto& l : layers) l.struct_size = sizeof(ft_splat_params);
  EXPECT_EQ(ft_splat_rules_layers(rules, layers.data(), n, &n), FT_OK) << ft_last_error();
  return layers;
}

TEST(SplatCapi, RulesFileGivesItsLayersWithDefaultsForTheRest) {
  const std::string path = write_file("good.json", R"({"layers": [
      {"name": "red", "color": [1, 0, 0]},
      {"name": "rock", "slope_min": 30, "slope_blend": 8, "weight": 3}]})");
  ft_splat_rules* rules = nullptr;
  ASSERT_EQ(ft_splat_rules_read(path.c_str(), &rules), FT_OK) << ft_last_error();
  const auto layers = layers_of(rules);
  ASSERT_EQ(layers.size(), 2u);
  ft_splat_params defaults;
  ASSERT_EQ(ft_splat_params_init(&defaults), FT_OK);
  EXPECT_STREQ(layers[0].name, "red");
  EXPECT_EQ(layers[0].color[0], 1.0);
  EXPECT_EQ(layers[0].color[1], 0.0);
  EXPECT_EQ(layers[0].slope_max, defaults.slope_max);
  EXPECT_STREQ(layers[1].name, "rock");
  EXPECT_EQ(layers[1].slope_min, 30.0);
  EXPECT_EQ(layers[1].weight, 3.0);
  EXPECT_EQ(layers[1].color[0], defaults.color[0]);
  // A one-red-layer rule set colours every sample red.
  ft_heightfield* hf = nullptr;
  const std::vector<float> z = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  ASSERT_EQ(ft_heightfield_create(3, 3, z.data(), &hf), FT_OK);
  std::vector<float> rgb(27);
  ASSERT_EQ(ft_splat_colors(hf, nullptr, nullptr, layers.data(), 1, rgb.data(), rgb.size()), FT_OK);
  for (size_t i = 0; i < 9; ++i) EXPECT_EQ((std::vector<float>{rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]}),
                                           (std::vector<float>{1, 0, 0}));
  ft_heightfield_free(hf);
  ft_splat_rules_free(rules);
  ft_splat_rules_free(nullptr);  // harmless
  fs::remove(path);
}

TEST(SplatCapi, BadRulesFilesAreRefusedWithWhatIsWrong) {
  struct Case {
    const char* text;
    ft_status status;
    const char* said;
  };
  for (const Case& c : {Case{R"({"layers": [{"name": "rock", "slop_min": 30}]})", FT_ERR_INVALID_ARGUMENT,
                             "layer 0 ('rock'): unknown field 'slop_min'"},
                        Case{R"({"layers": [{"name": "a"}, {"name": "a"}]})", FT_ERR_INVALID_ARGUMENT, "used twice"},
                        Case{R"({"layers": [{"name": "a", "weight": -1}]})", FT_ERR_INVALID_ARGUMENT, "weight"},
                        Case{"{not json", FT_ERR_FORMAT, "not JSON"}}) {
    const std::string path = write_file("bad.json", c.text);
    ft_splat_rules* rules = reinterpret_cast<ft_splat_rules*>(&rules);  // not NULL: the call must clear it
    EXPECT_EQ(ft_splat_rules_read(path.c_str(), &rules), c.status) << c.text;
    EXPECT_EQ(rules, nullptr);
    const std::string message = ft_last_error();
    EXPECT_NE(message.find(path), std::string::npos) << message;
    EXPECT_NE(message.find(c.said), std::string::npos) << message;
    fs::remove(path);
  }
  ft_splat_rules* rules = nullptr;
  EXPECT_EQ(ft_splat_rules_read("/no/such/rules.json", &rules), FT_ERR_IO);
  EXPECT_NE(std::string(ft_last_error()).find("/no/such/rules.json"), std::string::npos);
  EXPECT_EQ(ft_splat_rules_read(nullptr, &rules), FT_ERR_INVALID_ARGUMENT);
  int32_t n = 0;
  EXPECT_EQ(ft_splat_rules_layers(nullptr, nullptr, 0, &n), FT_ERR_INVALID_ARGUMENT);
}

TEST(SplatCapi, LinearRgbaRefusesBadArgumentsNamingThemAndCancels) {
  // ft_splat_colors_linear_rgba (ABI 2.25) checks what ctypes hands it: the
  // output and its size, the thread count; a callback's non-zero cancels.
  int32_t n = 0;
  ASSERT_EQ(ft_splat_default_layers(nullptr, 0, &n), FT_OK);
  std::vector<ft_splat_params> layers(static_cast<size_t>(n));
  for (auto& l : layers) l.struct_size = sizeof(ft_splat_params);
  ASSERT_EQ(ft_splat_default_layers(layers.data(), n, &n), FT_OK);
  ft_heightfield* hf = nullptr;
  const std::vector<float> z = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  ASSERT_EQ(ft_heightfield_create(3, 3, z.data(), &hf), FT_OK);
  std::vector<float> rgba(36);
  auto call = [&](int32_t threads, ft_progress_fn progress, float* out, size_t count) {
    return ft_splat_colors_linear_rgba(hf, nullptr, nullptr, layers.data(), n, threads, progress, nullptr, out, count);
  };
  EXPECT_EQ(call(0, nullptr, rgba.data(), rgba.size()), FT_OK) << ft_last_error();
  EXPECT_EQ(rgba[3], 1.0f);
  for (auto [threads, out, count, said] :
       {std::tuple{0, rgba.data(), size_t(35), "rgba holds 35 values; it needs 36"},
        std::tuple{0, static_cast<float*>(nullptr), size_t(36), "rgba"}, std::tuple{-1, rgba.data(), size_t(36), "threads"},
        std::tuple{1025, rgba.data(), size_t(36), "threads"}}) {
    EXPECT_EQ(call(threads, nullptr, out, count), FT_ERR_INVALID_ARGUMENT) << said;
    EXPECT_NE(std::string(ft_last_error()).find(said), std::string::npos) << ft_last_error();
  }
  EXPECT_EQ(call(1, [](void*, double) -> int32_t { return 1; }, rgba.data(), rgba.size()), FT_ERR_CANCELLED);
  ft_heightfield_free(hf);
}

}  // namespace
