// SPDX-License-Identifier: GPL-3.0-or-later
// Tile sets of eroded terrains (`fracterra tiles --erode`, tiles/ over
// pipeline/'s windows): every tile and every map tile is the same window of
// the whole eroded terrain, bit for bit, in any order of writing, after an
// interrupted run, on any thread count; the range is the whole's exact one;
// the engine tiles' splat maps are the whole's; bad input is refused before
// anything is written.
//
// The reference is the whole terrain built in memory by the pipeline
// (pipeline::build_terrain, what `fracterra terrain --erode` writes),
// independent of the tile code.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_run.hpp"
#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/erosion_params.hpp"
#include "io/atomic_file.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"
#include "pipeline/build_params.hpp"
#include "pipeline/terrain_build.hpp"
#include "splat/splat_map.hpp"
#include "terrain/terrain.hpp"
#include "tiles/height_range.hpp"
#include "tiles/manifest.hpp"
#include "tiles/tile_terrain.hpp"
#include "tiles/tileset.hpp"
#include "tiles/tileset_reader.hpp"

using namespace ft;
namespace fs = std::filesystem;

namespace {

// The add-on's default mountain at 257^2 (10 world units across).
ft_terrain_params mountain(uint64_t seed) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.levels = 8;
  p.seed = seed;
  p.sigma = 2.0;
  p.levelling = 1.0;
  p.height_offset = 1.5;
  p.falloff = FT_FALLOFF_RADIAL;
  p.falloff_width = 0.9;
  p.world_size = 10.0;
  p.threads = 2;
  return p;
}

// A terrain and its erosion, kept alive together (ft_build_params points into it).
struct Eroded {
  ft_terrain_params terrain;
  ft_erosion_params erosion = defaults_of<ft_erosion_params>(erosion::erosion_param_table());
  bool given = false;  // the erosion settings are given (else the preset's alone)
  int32_t preset = FT_EROSION_PRESET_LAND;

  ft_build_params build() const {
    ft_build_params b = defaults_of<ft_build_params>(pipeline::build_param_table());
    b.terrain = &terrain;
    b.erosion = given ? &erosion : nullptr;
    b.erosion_preset = preset;
    b.threads = terrain.threads;
    return b;
  }
  tiles::TileTerrain tiles(bool maps) const { return tiles::TileTerrain::of(build(), maps); }
};

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("ft_eroded_tiles_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

// The range pass and every tile, in the order given (a list of (col, row)), as one process does it.
void write_set(tiles::TileSet& set, const tiles::TileTerrain& t, const std::vector<std::pair<int, int>>& order) {
  if (set.range_pending()) {
    double lo = INFINITY, hi = -INFINITY;
    for (auto [c, r] : order) {
      const tiles::HeightRange h = tiles::tile_height_range(t, set.spec(), set.dir(), c, r);
      lo = std::min(lo, h.min), hi = std::max(hi, h.max);
    }
    set.set_height_range(lo, hi);
  }
  for (auto [c, r] : order)
    if (!set.done(c, r)) set.record(c, r, tiles::write_tile(t, set.spec(), set.dir(), c, r));
  set.finish();
}

std::vector<std::pair<int, int>> row_major(int columns, int rows) {
  std::vector<std::pair<int, int>> v;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) v.emplace_back(c, r);
  return v;
}

// Samples of `tile` that differ from the window at (x0, y0) of `whole`.
int64_t differences(const Heightfield& tile, const Heightfield& whole, int64_t x0, int64_t y0) {
  int64_t off = 0;
  for (int32_t y = 0; y < tile.height(); ++y)
    for (int32_t x = 0; x < tile.width(); ++x) {
      const float a = tile.at(x, y), b = whole.at(int32_t(x0 + x), int32_t(y0 + y));
      off += std::memcmp(&a, &b, sizeof a) != 0;
    }
  return off;
}

// {file name: bytes} of every file under `dir` (relative names).
std::map<std::string, std::string> files(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = io::read_file(e.path().string());
  return out;
}

}  // namespace

// Every height tile and every map tile of an eroded set is the same window of
// the whole eroded terrain, bit for bit; the set's range is the whole's
// exact range; the range pass's pending folder is gone when the set is
// finished. Broken on purpose (the tiles cut from a whole built with the
// erosion's strength 0.5 while the set said 0.7; the pending folder read
// back one tile off): this test failed.
TEST(ErodedTiles, TilesAndMapsAreTheWholesWindowsBitForBit) {
  Eroded e{mountain(5)};
  e.given = true;
  e.erosion.strength = 0.7;
  const tiles::TileTerrain t = e.tiles(true);
  const fs::path dir = fresh_dir("whole");
  tiles::TileSet set(t, 64, tiles::TileFormat::tiff, dir.string(), true);
  ASSERT_TRUE(set.range_pending());  // eroded: the exact pass
  write_set(set, t, row_major(4, 4));

  erosion::ErosionMaps maps;
  const Heightfield whole = pipeline::build_terrain(e.build(), &maps);
  const HeightStats s = whole.stats();
  EXPECT_EQ(set.spec().height_min, s.min);
  EXPECT_EQ(set.spec().height_max, s.max);
  for (int32_t row = 0; row < 4; ++row)
    for (int32_t col = 0; col < 4; ++col) {
      const Heightfield h = io::read_heightfield((dir / tiles::tile_file_name(set.spec(), col, row)).string());
      ASSERT_EQ(h.width(), 65);
      EXPECT_EQ(differences(h, whole, col * 64, row * 64), 0) << "heights of tile " << col << ", " << row;
      for (int k = 0; k < FT_MAP_COUNT; ++k) {
        const Heightfield m = io::read_heightfield((dir / tiles::map_file_name(set.spec(), k, col, row)).string());
        EXPECT_EQ(differences(m, tiles::map_of(maps, k), col * 64, row * 64), 0)
            << tiles::kMapNames[size_t(k)] << " of tile " << col << ", " << row;
      }
    }
  // Read back through the reader, across tiles: the whole again.
  EXPECT_EQ(differences(tiles::read_tileset_window(dir.string(), 0, 0, 0, 257, 257), whole, 0, 0), 0);
  EXPECT_EQ(differences(tiles::read_tileset_map_window(dir.string(), "deposited", 0, 30, 40, 150, 100),
                        maps.deposited, 30, 40),
            0);
  const nlohmann::json m = *tiles::read_manifest(dir.string());
  EXPECT_EQ(m["erosion"]["preset"], "land");
  EXPECT_EQ(m["erosion"]["strength"], 0.7);
  EXPECT_EQ(m["maps"].size(), size_t(FT_MAP_COUNT));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().rfind(".pending-", 0), 0u) << entry.path();
  fs::remove_all(dir);
}

// 16-bit tiles of an eroded set (with a sea and a periodic terrain too) are
// the whole quantised on its exact range: neighbours agree on their shared
// edges to the code.
TEST(ErodedTiles, Png16TilesAreTheQuantisedWholeWithASeaAndOnATorus) {
  for (const bool periodic : {false, true}) {
    Eroded e{mountain(9)};
    e.preset = FT_EROSION_PRESET_VALLEYS;
    if (periodic) {
      e.terrain.periodic = 1;
      e.terrain.falloff = FT_FALLOFF_NONE;
    } else {
      e.terrain.sea = FT_SEA_HEIGHT;
      e.terrain.sea_level = 1.6;
    }
    const tiles::TileTerrain t = e.tiles(false);
    const fs::path dir = fresh_dir(periodic ? "torus" : "sea");
    tiles::TileSet set(t, 128, tiles::TileFormat::png16, dir.string(), true);
    write_set(set, t, row_major(2, 2));
    const Heightfield whole = pipeline::build_terrain(e.build(), nullptr);
    const double lo = whole.stats().min, hi = whole.stats().max;
    EXPECT_EQ(set.spec().height_min, lo);
    EXPECT_EQ(set.spec().height_max, hi);
    for (int32_t row = 0; row < 2; ++row)
      for (int32_t col = 0; col < 2; ++col) {
        const GrayImage img = io::read_png((dir / tiles::tile_file_name(set.spec(), col, row)).string());
        int64_t off = 0;
        for (int32_t y = 0; y < img.height; ++y)
          for (int32_t x = 0; x < img.width; ++x)
            off += img.pixels[size_t(y) * size_t(img.width) + size_t(x)] !=
                   uint16_t(std::nearbyint((whole.at(col * 128 + x, row * 128 + y) - lo) * 65535.0 / (hi - lo)));
        EXPECT_EQ(off, 0) << (periodic ? "torus" : "sea") << ", tile " << col << ", " << row;
      }
    fs::remove_all(dir);
  }
}

// A run killed part way (after the range pass, with some tiles written, a
// tile's maps moved into place but its heights not yet written, a
// temporary file left behind) and resumed in another order gives the same
// bytes as an undisturbed run, file for file.
TEST(ErodedTiles, AnInterruptedRunResumesToTheSameBytes) {
  Eroded e{mountain(3)};
  const tiles::TileTerrain t = e.tiles(true);
  const fs::path straight = fresh_dir("straight"), dir = fresh_dir("resumed");
  {
    tiles::TileSet set(t, 128, tiles::TileFormat::png16, straight.string(), true);
    write_set(set, t, row_major(2, 2));
  }
  {
    tiles::TileSet set(t, 128, tiles::TileFormat::png16, dir.string(), true);
    double lo = INFINITY, hi = -INFINITY;
    for (auto [c, r] : row_major(2, 2)) {
      const tiles::HeightRange h = tiles::tile_height_range(t, set.spec(), set.dir(), c, r);
      lo = std::min(lo, h.min), hi = std::max(hi, h.max);
    }
    set.set_height_range(lo, hi);
    set.record(1, 1, tiles::write_tile(t, set.spec(), set.dir(), 1, 1));
    // Tile (0, 1): its maps were moved into place, then the writer died.
    const fs::path pending = fs::path(tiles::pending_path(set.spec(), set.dir()));
    for (int k = 0; k < FT_MAP_COUNT; ++k) {
      const fs::path to = dir / tiles::map_file_name(set.spec(), k, 0, 1);
      fs::create_directories(to.parent_path());
      fs::rename(pending / tiles::map_file_name(set.spec(), k, 0, 1), to);
    }
    // A writer killed while writing tile (0, 0) (its temporary name carries a pid that is gone).
    io::write_file_atomically((dir / ".tile_r000_c000.png.tmp.4194301.aaaaaa").string(), "torn");
  }  // the process ends here
  {
    tiles::TileSet set(t, 128, tiles::TileFormat::png16, dir.string(), true);
    EXPECT_FALSE(set.range_pending());
    EXPECT_TRUE(set.done(1, 1));
    EXPECT_FALSE(set.done(0, 1));
    write_set(set, t, {{0, 1}, {1, 0}, {0, 0}, {1, 1}});
  }
  const auto want = files(straight), got = files(dir);
  ASSERT_EQ(got.size(), want.size());
  for (const auto& [name, bytes] : want) {
    ASSERT_TRUE(got.count(name)) << name;
    EXPECT_TRUE(got.at(name) == bytes) << name;
  }
  fs::remove_all(straight);
  fs::remove_all(dir);
}

// The tiles' bits do not depend on the thread count.
TEST(ErodedTiles, TheSameBytesOnOneAndTwoThreads) {
  std::map<std::string, std::string> sets[2];
  for (int threads : {1, 2}) {
    Eroded e{mountain(4)};
    e.terrain.threads = threads;
    const tiles::TileTerrain t = e.tiles(false);
    const fs::path dir = fresh_dir("threads" + std::to_string(threads));
    tiles::TileSet set(t, 128, tiles::TileFormat::png16, dir.string(), true);
    write_set(set, t, row_major(2, 2));
    sets[threads - 1] = files(dir);
    fs::remove_all(dir);
  }
  EXPECT_TRUE(sets[0] == sets[1]);
}

// A folder holding a set of another erosion (another preset, strength or
// none at all) or without the maps is refused naming the difference, and
// nothing in it changes.
TEST(ErodedTiles, AFolderOfAnotherErosionIsRefusedAndKept) {
  Eroded e{mountain(6)};
  const fs::path dir = fresh_dir("other");
  {
    tiles::TileSet set(e.tiles(false), 128, tiles::TileFormat::png16, dir.string(), true);
    write_set(set, e.tiles(false), row_major(2, 2));
  }
  const auto before = files(dir);
  auto refused = [&](const tiles::TileTerrain& t, const std::string& why) {
    try {
      tiles::TileSet set(t, 128, tiles::TileFormat::png16, dir.string(), true);
      ADD_FAILURE() << "not refused: " << why;
    } catch (const Error& err) {
      EXPECT_NE(std::string(err.what()).find(why), std::string::npos) << err.what();
    }
    EXPECT_TRUE(files(dir) == before) << why;
  };
  Eroded stronger = e;
  stronger.given = true;
  stronger.erosion.strength = 0.9;
  refused(stronger.tiles(false), "erosion strength: 0.9 here, 0.5 in the folder");
  Eroded badlands = e;
  badlands.preset = FT_EROSION_PRESET_BADLANDS;
  refused(badlands.tiles(false), "erosion: preset badlands here, preset land in the folder");
  refused(tiles::TileTerrain::of(e.terrain), "erosion: none here, preset land in the folder");
  refused(e.tiles(true), "maps: kept here, none in the folder");
  fs::remove_all(dir);
}

// An engine's tiles of an eroded set carry the default rules' splat maps,
// equal to those of the whole set read back as one terrain (its heights and
// maps): the rules see the whole's height range and area, and slopes at a
// tile's edges reach into its neighbours. Broken on purpose (each tile's own
// range; no margin): this test failed.
TEST(ErodedTiles, EngineTilesCarryTheWholesSplatMaps) {
  const fs::path dir = fresh_dir("engine");
  const test::CliRun run = test::run_cli(
      "tiles --method midpoint --levels 8 --seed 2 --sigma 2 --levelling 1 --height-offset 1.5 --falloff radial "
      "--falloff-width 0.9 --world-size 10 --erode land --maps --tile 64 --quiet --engine unity --out " +
      dir.string());
  ASSERT_EQ(run.code, 0) << run.err;
  const Heightfield whole = tiles::read_tileset_window(dir.string(), 0, 0, 0, 257, 257);
  const Heightfield deposited = tiles::read_tileset_map_window(dir.string(), "deposited", 0, 0, 0, 257, 257);
  const Heightfield area = tiles::read_tileset_map_window(dir.string(), "drainage_area", 0, 0, 0, 257, 257);
  const auto layers = splat::default_layers();
  const int32_t n = int32_t(layers.size());
  const std::vector<uint16_t> want = splat::splat_weights({&whole, &deposited, &area}, layers.data(), n, 255);
  const nlohmann::json side = nlohmann::json::parse(io::read_file((dir / "unity" / "unity.json").string()));
  ASSERT_EQ(side["files"].size(), 16u);
  for (const nlohmann::json& f : side["files"]) {
    const io::ChannelImage img = io::read_png_channels((dir / "unity" / f["splat_file"].get<std::string>()).string());
    ASSERT_EQ(img.width, 65);
    ASSERT_EQ(img.channels, 4);
    const int64_t x0 = f["x"].get<int64_t>() * 64, y0 = f["y"].get<int64_t>() * 64;
    int64_t off = 0;
    for (int32_t y = 0; y < 65; ++y)
      for (int32_t x = 0; x < 65; ++x)
        for (int32_t k = 0; k < n; ++k)
          off += img.samples[(size_t(y) * 65 + size_t(x)) * 4 + size_t(k)] !=
                 want[(size_t(y0 + y) * 257 + size_t(x0 + x)) * size_t(n) + size_t(k)];
    EXPECT_EQ(off, 0) << f["splat_file"];
  }
  fs::remove_all(dir);
}

// Bad input is refused with a clear message before anything is written: an
// erosion preset the library does not know, a tile size that does not cut an
// eroded set, an erosion mask of another shape than the whole.
TEST(ErodedTiles, BadInputIsRefusedAndWritesNothing) {
  const std::string terrain = "tiles --method midpoint --levels 8 --seed 2 --quiet ";
  auto refused = [&](const std::string& args, const std::string& why) {
    const fs::path dir = fresh_dir("bad");
    const test::CliRun run = test::run_cli(terrain + args + " --out " + dir.string());
    EXPECT_NE(run.code, 0) << args;
    EXPECT_NE(run.err.find(why), std::string::npos) << args << ": " << run.err;
    EXPECT_FALSE(fs::exists(dir)) << args << " wrote " << dir;
    fs::remove_all(dir);
  };
  refused("--erode rugged --tile 64", "must be one of none, valleys");
  refused("--erode land --tile 100", "does not cut");
  const fs::path mask = fs::temp_directory_path() / ("ft_eroded_tiles_mask_" + std::to_string(::getpid()) + ".npy");
  Heightfield m(65, 33);
  for (size_t i = 0; i < m.size(); ++i) m.data()[i] = 1.0f;
  io::write_heightfield(m, mask.string());
  refused("--erode land --tile 64 --erosion-mask " + mask.string(), "the erosion mask is 65 x 33");
  fs::remove(mask);
  fs::remove(mask.string() + ".json");  // its sidecar (the world size)
}

// Without --maps an eroded set is cut for an engine with its heights alone
// (the splat maps come from the erosion maps, whose drainage area makes each
// task build the whole): the run says so, and no tile carries a splat map.
TEST(ErodedTiles, EngineTilesWithoutMapsAreHeightsAlone) {
  const fs::path dir = fresh_dir("engine_heights");
  const test::CliRun run = test::run_cli(
      "tiles --method midpoint --levels 8 --seed 2 --world-size 10 --erode land --tile 64 --quiet --engine unity "
      "--out " + dir.string());
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.err.find("no splat maps"), std::string::npos) << run.err;
  const nlohmann::json side = nlohmann::json::parse(io::read_file((dir / "unity" / "unity.json").string()));
  EXPECT_FALSE(side.contains("splat_layers"));
  ASSERT_EQ(side["files"].size(), 16u);
  for (const nlohmann::json& f : side["files"]) {
    EXPECT_FALSE(f.contains("splat_file")) << f;
    EXPECT_TRUE(fs::exists(dir / "unity" / f["file"].get<std::string>())) << f;
  }
  fs::remove_all(dir);
}

// `fracterra rivers --tiles` on a float tile set traces the same network as
// `fracterra rivers --in` on the whole eroded terrain (written by `fracterra
// terrain --erode`): the same segments, vertices and lakes, file for file.
// Broken on purpose (the set read one sample short): this test failed.
TEST(ErodedTiles, RiversOnATileSetAreTheRiversOfTheWhole) {
  const fs::path dir = fresh_dir("rivers");
  fs::create_directories(dir);
  const std::string terrain =
      "--method midpoint --levels 8 --seed 2 --sigma 2 --levelling 1 --height-offset 1.5 --falloff radial "
      "--falloff-width 0.9 --world-size 10 --erode land ";
  ASSERT_EQ(test::run_cli("terrain " + terrain + "--out " + (dir / "whole.tif").string()).code, 0);
  const test::CliRun set = test::run_cli("tiles " + terrain + "--tile 64 --format tiff --quiet --out " +
                                         (dir / "set").string());
  ASSERT_EQ(set.code, 0) << set.err;
  const std::string flags = " --min-area 0.05 --stats --out ";
  const test::CliRun a = test::run_cli("rivers --in " + (dir / "whole.tif").string() + flags + (dir / "a.json").string());
  const test::CliRun b = test::run_cli("rivers --tiles " + (dir / "set").string() + flags + (dir / "b.json").string());
  ASSERT_EQ(a.code, 0) << a.err;
  ASSERT_EQ(b.code, 0) << b.err;
  const nlohmann::json sa = nlohmann::json::parse(a.out), sb = nlohmann::json::parse(b.out);
  EXPECT_GT(sa["segments"].get<int64_t>(), 10);
  for (const char* key : {"segments", "vertices", "lakes", "total_length"}) EXPECT_EQ(sa[key], sb[key]) << key;
  EXPECT_TRUE(io::read_file((dir / "a.json").string()) == io::read_file((dir / "b.json").string()));
  fs::remove_all(dir);
}
