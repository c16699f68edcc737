// SPDX-License-Identifier: GPL-3.0-or-later
// The rivers stage of the library's pipeline is what the CLI writes:
// `fracterra terrain ... --rivers r.json` is ft::pipeline::build_terrain with
// rivers, point for point, on a tiling terrain (where the torus rule matters)
// and a bounded one. Broken (the CLI deciding periodicity itself, spectral
// only, as it did): the periodic case differs in its segment count.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "hydrology/river_files.hpp"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"
#include "terrain/terrain.hpp"

namespace ft::pipeline {
namespace {

TEST(PipelineRivers, TheCliWritesTheLibrarysRivers) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("ft_pipeline_rivers_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  for (const bool periodic : {true, false}) {
    const std::string json = (dir / "r.json").string();
    const std::string cmd = std::string(FT_CLI_PATH) + " terrain --method midpoint --levels 7 --seed 3 " +
                            (periodic ? "--periodic " : "") + "--erode valleys --threads 2 --rivers " + json +
                            " > " + (dir / "log.txt").string() + " 2>&1";
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    const hydrology::WaterScene cli = hydrology::read_water_json(json);

    ft_terrain_params t = terrain::default_terrain_params();
    t.method = FT_TERRAIN_MIDPOINT;
    t.levels = 7;
    t.seed = 3;
    t.periodic = periodic;
    ft_build_params b = defaults_of<ft_build_params>(build_param_table());
    b.terrain = &t;
    b.erosion_preset = FT_EROSION_PRESET_VALLEYS;
    b.threads = 2;
    hydrology::RiverNetwork net;
    build_terrain(b, nullptr, &net);

    ASSERT_EQ(cli.rivers.line_count(), net.lines.line_count()) << "periodic " << periodic;
    ASSERT_EQ(cli.rivers.points.size(), net.lines.points.size()) << "periodic " << periodic;
    for (size_t v = 0; v < net.lines.points.size(); ++v)
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(cli.rivers.points[v][k], net.lines.points[v][k], 1e-9) << "vertex " << v;
    EXPECT_EQ(cli.lakes.size(), net.water.lakes.size());
  }
  fs::remove_all(dir);
}

// The landform's sea is erosion's base level in the pipeline (so in the CLI
// and Blender alike). An eroded island keeps its sea floor to the bit, no
// land sinks below it, and its rivers end in it. Before, the sediment built
// the sea floor up into sand flats and specks.
void expect_the_island_keeps_its_sea(const ft_terrain_params& t, float level) {
  const Heightfield before = terrain::generate_terrain(t);
  ft_build_params b = defaults_of<ft_build_params>(build_param_table());
  b.terrain = &t;
  b.erosion_preset = FT_EROSION_PRESET_LAND;
  b.threads = 2;
  hydrology::RiverNetwork net;
  const Heightfield after = build_terrain(b, nullptr, &net);
  size_t sea = 0, changed = 0, sunk = 0;
  for (size_t i = 0; i < before.size(); ++i) {
    if (before.data()[i] <= level) ++sea, changed += after.data()[i] != before.data()[i];
    else sunk += after.data()[i] < level;
  }
  EXPECT_GT(sea, before.size() / 4);
  EXPECT_EQ(changed, 0u);
  EXPECT_EQ(sunk, 0u);
  size_t to_sea = 0;
  for (const auto& s : net.segments) to_sea += s.end == hydrology::RiverEnd::kSea;
  EXPECT_GT(to_sea, 10u) << "of " << net.segments.size() << " segments";
}

ft_terrain_params island() {
  ft_terrain_params t = terrain::default_terrain_params();
  t.method = FT_TERRAIN_FBM;
  t.width = t.height = 257;
  t.seed = 7;
  t.hurst = 0.8;
  t.world_size = 10;
  return t;
}

TEST(PipelineRivers, AnErodedIslandKeepsItsSeaAndItsRiversEndInIt) {
  ft_terrain_params t = island();
  t.sea = FT_SEA_FRACTION;
  t.sea_fraction = 0.3;
  expect_the_island_keeps_its_sea(t, terrain::generate_terrain(t).stats().min);
}

// A sea given as a height whose float lies above it (0.1 does: float(0.1) is
// 0.10000000149): the landform flattens the sea to the float, and erosion,
// comparing in double, found no sea at all; the sea floor eroded, and no
// river ended in it.
TEST(PipelineRivers, ASeaAtAHeightThatRoundsUpAsAFloatIsKept) {
  ft_terrain_params t = island();
  t.sea = FT_SEA_FRACTION;
  t.sea_fraction = 0.3;
  const float at_fraction = terrain::generate_terrain(t).stats().min;
  // The double a quarter of a float step under that sample: it rounds to it.
  const double level = double(at_fraction) - 0.25 * (double(std::nextafter(at_fraction, INFINITY)) - at_fraction);
  ASSERT_GT(double(float(level)), level);
  t.sea = FT_SEA_HEIGHT;
  t.sea_level = level;
  expect_the_island_keeps_its_sea(t, float(level));
}

}  // namespace
}  // namespace ft::pipeline
