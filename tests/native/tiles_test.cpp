// SPDX-License-Identifier: GPL-3.0-or-later
// Tile sets (native/src/tiles/, `fracterra tiles`): tiles share their edge
// samples and one height scale, so neighbouring 16-bit tiles agree exactly on
// their shared edges and every tile is the quantised window of the whole
// terrain; the height range holds the whole; a rerun resumes (skips tiles
// whose CRC-32 matches, from a journal of finished tiles) and a folder
// holding another terrain is refused; the exact height range can come from
// per-tile tasks; the
// VRT mosaic has the whole's size in gdalinfo.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/increment_sums.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "io/png_image.hpp"
#include "terrain/terrain.hpp"
#include "tiles/height_range.hpp"
#include "tiles/manifest.hpp"
#include "tiles/tileset.hpp"
#include "tiles/tileset_reader.hpp"

using namespace ft;
namespace fs = std::filesystem;

namespace {

ft_terrain_params midpoint(int levels, uint64_t seed) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.levels = levels;
  p.hurst = 0.7;
  p.seed = seed;
  p.threads = 2;
  return p;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("ft_tiles_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

// Writes every tile of `set` not yet done; returns how many it wrote.
int write_all(tiles::TileSet& set, const ft_terrain_params& p) {
  int n = 0;
  for (int32_t row = 0; row < set.spec().grid.rows(); ++row)
    for (int32_t col = 0; col < set.spec().grid.columns(); ++col)
      if (!set.done(col, row)) set.record(col, row, tiles::write_tile(p, set.spec(), set.dir(), col, row)), ++n;
  return n;
}

std::string run(const std::string& command) {
  std::string out;
  FILE* f = popen((command + " 2>&1").c_str(), "r");
  char buf[4096];
  while (size_t n = fread(buf, 1, sizeof buf, f)) out.append(buf, n);
  const int status = pclose(f);
  return (status == 0 ? "" : "FAILED: ") + out;
}

}  // namespace

TEST(Tiles, GridSharesEdgesAndCoversTheWhole) {
  const tiles::TileGrid g = tiles::make_tile_grid(513, 300, 128);
  EXPECT_EQ(g.columns(), 4);
  EXPECT_EQ(g.rows(), 3);  // rows start at 0, 128, 256; the last holds 44 samples
  EXPECT_EQ(g.window(1, 0).x0, 128);
  EXPECT_EQ(g.window(1, 0).width, 129);
  EXPECT_EQ(g.window(3, 2).width, 129);
  EXPECT_EQ(g.window(3, 2).height, 300 - 256);
  EXPECT_THROW(tiles::make_tile_grid(513, 513, 1), Error);
  EXPECT_THROW(g.check_tile(4, 0), Error);
}

// Every 16-bit tile is the whole terrain quantised with the set's one range:
// so neighbours agree exactly on their shared edge samples.
TEST(Tiles, Png16TilesAreTheQuantisedWholeAndEdgesAgree) {
  const ft_terrain_params p = midpoint(9, 7);  // 513^2, tiles of 129^2
  const fs::path dir = fresh_dir("png");
  tiles::TileSet set(p, 128, tiles::TileFormat::png16, dir.string());
  EXPECT_EQ(write_all(set, p), 16);
  const Heightfield whole = terrain::generate_terrain(p);
  const double lo = set.spec().height_min, hi = set.spec().height_max;
  const HeightStats s = whole.stats();
  EXPECT_EQ(lo, s.min);  // levels <= 12: the range pass is the whole terrain, exact
  EXPECT_EQ(hi, s.max);
  std::vector<GrayImage> tiles;
  for (int32_t row = 0; row < 4; ++row)
    for (int32_t col = 0; col < 4; ++col) {
      tiles.push_back(io::read_png((dir / tiles::tile_file_name(set.spec(), col, row)).string()));
      const GrayImage& t = tiles.back();
      ASSERT_EQ(t.width, 129);
      int64_t off = 0;
      for (int32_t y = 0; y < t.height; ++y)
        for (int32_t x = 0; x < t.width; ++x) {
          const double z = whole.at(col * 128 + x, row * 128 + y);
          off += t.pixels[size_t(y) * 129 + size_t(x)] != uint16_t(std::nearbyint((z - lo) * 65535.0 / (hi - lo)));
        }
      EXPECT_EQ(off, 0) << "tile " << col << ", " << row;
    }
  int64_t edge_mismatches = 0;
  for (int32_t row = 0; row < 4; ++row)
    for (int32_t col = 0; col < 4; ++col) {
      const GrayImage& t = tiles[size_t(row * 4 + col)];
      for (int32_t k = 0; k < 129; ++k) {
        if (col < 3) edge_mismatches += t.pixels[size_t(k) * 129 + 128] != tiles[size_t(row * 4 + col + 1)].pixels[size_t(k) * 129];
        if (row < 3) edge_mismatches += t.pixels[128 * 129 + size_t(k)] != tiles[size_t((row + 1) * 4 + col)].pixels[size_t(k)];
      }
    }
  EXPECT_EQ(edge_mismatches, 0);
  fs::remove_all(dir);
}

// TIFF tiles hold the exact float heights of the whole.
TEST(Tiles, TiffTilesHoldTheExactWindow) {
  ft_terrain_params p = midpoint(8, 3);
  p.method = FT_TERRAIN_ADDITIONS;  // additions: exact range pass
  const fs::path dir = fresh_dir("tiff");
  tiles::TileSet set(p, 100, tiles::TileFormat::tiff, dir.string());  // 257: tiles at 0, 100, 200 (the last 57 wide)
  EXPECT_EQ(write_all(set, p), 9);
  const Heightfield whole = terrain::generate_terrain(p);
  EXPECT_EQ(set.spec().height_min, whole.stats().min);
  EXPECT_EQ(set.spec().height_max, whole.stats().max);
  const Heightfield t = io::read_heightfield((dir / tiles::tile_file_name(set.spec(), 2, 1)).string());
  ASSERT_EQ(t.width(), 57);
  ASSERT_EQ(t.height(), 101);
  int64_t off = 0;
  for (int32_t y = 0; y < t.height(); ++y)
    for (int32_t x = 0; x < t.width(); ++x) off += t.at(x, y) != whole.at(200 + x, 100 + y);
  EXPECT_EQ(off, 0);
  fs::remove_all(dir);
}

// The midpoint bound (height_range.hpp) holds the whole terrain, and is
// tight: from stage 12 of a 13-level terrain the margin is
// 5.9 sigma (2^-8.75 + 2^-9.1) (half-steps k = 25, 26 of sigma 2^(-k H / 2),
// H = 0.7), about 0.024 sigma a side, under 3% of the range both sides
// together (16-bit tiles lose under 0.05 bit of resolution to it).
TEST(Tiles, MidpointBoundHoldsTheWholeAndIsTight) {
  for (uint64_t seed : {1, 2}) {
    const ft_terrain_params p = midpoint(13, seed);  // 8193^2: the coarse pass is lod 1
    const tiles::HeightRange r = tiles::tileset_height_range(p, tiles::make_tile_grid(8193, 8193, 4096));
    EXPECT_EQ(r.how, "bound");
    const HeightStats s = terrain::generate_terrain(p).stats();
    EXPECT_LE(r.min, s.min);
    EXPECT_GE(r.max, s.max);
    const double margin = tiles::midpoint_bound_margin(13, 12, 0.7, 1.0);
    EXPECT_NEAR(margin, 5.9 * (std::pow(2.0, -8.75) + std::pow(2.0, -9.1)), 1e-12);
    // The coarse range lies inside the whole's, widened by the margin and the float slack.
    const double slack = 1e-5 * (std::max(std::abs(s.min), std::abs(s.max)) + margin);
    EXPECT_LE((s.min - r.min) + (r.max - s.max), 2.0 * (margin + slack) + 1e-12);
    EXPECT_LT(2.0 * margin, 0.03 * (s.max - s.min));
  }
}

TEST(Tiles, LandformsTakeTheExactRange) {
  // The midpoint bound covers the raw method's displacements only: with a
  // landform (here an island falloff) the range is the tiles' exact one.
  ft_terrain_params p = midpoint(9, 3);
  p.levelling = 1, p.height_offset = 1, p.falloff = FT_FALLOFF_RADIAL, p.falloff_width = 0.5, p.edge_level = -2;
  const tiles::HeightRange r = tiles::tileset_height_range(p, tiles::make_tile_grid(513, 513, 256));
  EXPECT_EQ(r.how, "exact");
  const HeightStats s = terrain::generate_terrain(p).stats();
  EXPECT_EQ(r.min, s.min);
  EXPECT_EQ(r.max, s.max);
}

TEST(Tiles, RerunSkipsTilesWhoseChecksumMatches) {
  const ft_terrain_params p = midpoint(8, 11);
  const fs::path dir = fresh_dir("resume");
  {
    tiles::TileSet set(p, 128, tiles::TileFormat::png16, dir.string());
    EXPECT_EQ(write_all(set, p), 4);
    set.finish();
  }
  tiles::TileSet again(p, 128, tiles::TileFormat::png16, dir.string());
  EXPECT_EQ(again.recorded(), 4);
  EXPECT_TRUE(again.done(1, 1));
  // A damaged tile and a missing one are written again, the others skipped.
  const fs::path damaged = dir / tiles::tile_file_name(again.spec(), 1, 0);
  {
    std::fstream f(damaged, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(200);
    f.put('\x5a');
  }
  fs::remove(dir / tiles::tile_file_name(again.spec(), 0, 1));
  EXPECT_FALSE(again.done(1, 0));
  EXPECT_FALSE(again.done(0, 1));
  EXPECT_EQ(write_all(again, p), 2);
  EXPECT_TRUE(again.done(1, 0));
  fs::remove_all(dir);
}

std::string file_text(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

// Recording n tiles must cost O(n): each record appends one line to the
// journal and leaves manifest.json alone (it used to rewrite it, O(n) each).
// A killed run's journal, torn last line included, is folded in on resume,
// and the finished set is the same bytes as an uninterrupted one.
TEST(Tiles, RecordingAppendsToAJournalFoldedInOnResume) {
  const ft_terrain_params p = midpoint(8, 11);
  const fs::path straight = fresh_dir("journal_straight"), dir = fresh_dir("journal");
  {
    tiles::TileSet set(p, 128, tiles::TileFormat::png16, straight.string());
    write_all(set, p);
    set.finish();
  }
  {
    tiles::TileSet set(p, 128, tiles::TileFormat::png16, dir.string());
    const std::string opened = file_text(dir / tiles::kManifestName);
    set.record(0, 0, tiles::write_tile(p, set.spec(), set.dir(), 0, 0));
    set.record(1, 0, tiles::write_tile(p, set.spec(), set.dir(), 1, 0));
    EXPECT_EQ(file_text(dir / tiles::kManifestName), opened);  // not rewritten
    const std::string journal = file_text(dir / tiles::kJournalName);
    EXPECT_EQ(std::count(journal.begin(), journal.end(), '\n'), 2) << journal;
    std::ofstream(dir / tiles::kJournalName, std::ios::app) << "{\"column\": 0, \"row\": 1, \"cr";  // killed mid-append
  }  // the run is killed here: no finish
  tiles::TileSet again(p, 128, tiles::TileFormat::png16, dir.string());
  EXPECT_FALSE(fs::exists(dir / tiles::kJournalName));  // folded into the manifest
  EXPECT_EQ(again.recorded(), 2);
  EXPECT_TRUE(again.done(0, 0));
  EXPECT_TRUE(again.done(1, 0));
  EXPECT_FALSE(again.done(0, 1));  // the torn line recorded nothing
  const nlohmann::json m = nlohmann::json::parse(file_text(dir / tiles::kManifestName));
  EXPECT_FALSE(m["tiles"][1]["crc32"].is_null());
  EXPECT_EQ(write_all(again, p), 2);
  again.finish();
  EXPECT_FALSE(fs::exists(dir / tiles::kJournalName));
  EXPECT_EQ(file_text(dir / tiles::kManifestName), file_text(straight / tiles::kManifestName));
  fs::remove_all(dir);
  fs::remove_all(straight);
}

// The exact range pass run elsewhere (Dask: one task per tile): a deferred
// set waits for the union of its tiles' ranges, writes nothing before it,
// and ends with the range the in-process pass gives.
TEST(Tiles, ExactRangeCanComeFromPerTileTasks) {
  ft_terrain_params p = midpoint(9, 3);
  p.falloff = FT_FALLOFF_RADIAL, p.falloff_width = 0.5, p.edge_level = -2;  // needs the exact pass
  ASSERT_TRUE(tiles::needs_exact_pass(p));
  const fs::path dir = fresh_dir("deferred");
  tiles::TileSet set(p, 128, tiles::TileFormat::png16, dir.string(), true);
  ASSERT_TRUE(set.range_pending());
  EXPECT_FALSE(fs::exists(dir / tiles::kManifestName));
  EXPECT_THROW(set.record(0, 0, 1), Error);
  EXPECT_THROW(set.finish(), Error);
  EXPECT_THROW(set.set_height_range(NAN, 1.0), Error);
  EXPECT_THROW(set.set_height_range(1.0, 0.0), Error);
  double lo = INFINITY, hi = -INFINITY;
  for (int32_t row = 0; row < set.spec().grid.rows(); ++row)
    for (int32_t col = 0; col < set.spec().grid.columns(); ++col) {
      const tiles::HeightRange t = tiles::tile_height_range(p, set.spec().grid, col, row);
      lo = std::min(lo, t.min), hi = std::max(hi, t.max);
    }
  set.set_height_range(lo, hi);
  EXPECT_FALSE(set.range_pending());
  EXPECT_THROW(set.set_height_range(lo, hi), Error);  // fixed once
  const tiles::HeightRange whole = tiles::tileset_height_range(p, set.spec().grid);
  EXPECT_EQ(set.spec().height_min, whole.min);
  EXPECT_EQ(set.spec().height_max, whole.max);
  EXPECT_EQ(write_all(set, p), 16);
  set.finish();
  EXPECT_EQ(tiles::TileSet(p, 128, tiles::TileFormat::png16, dir.string(), true).spec().height_max, whole.max);  // resumed
  // Plain midpoint keeps its bound from the coarse pass: never pending.
  const fs::path plain = fresh_dir("deferred_plain");
  EXPECT_FALSE(tiles::TileSet(midpoint(9, 3), 128, tiles::TileFormat::png16, plain.string(), true).range_pending());
  fs::remove_all(dir);
  fs::remove_all(plain);
}

TEST(Tiles, FolderOfAnotherTerrainIsRefused) {
  const ft_terrain_params p = midpoint(8, 11);
  const fs::path dir = fresh_dir("refuse");
  { tiles::TileSet set(p, 128, tiles::TileFormat::png16, dir.string()); }
  ft_terrain_params q = p;
  q.hurst = 0.5;
  try {
    tiles::TileSet other(q, 128, tiles::TileFormat::png16, dir.string());
    FAIL() << "another terrain's folder was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("hurst: 0.5 here, 0.7 in the folder"), std::string::npos) << e.what();
  }
  EXPECT_THROW(tiles::TileSet(p, 64, tiles::TileFormat::png16, dir.string()), Error);   // another tile size
  EXPECT_THROW(tiles::TileSet(p, 128, tiles::TileFormat::tiff, dir.string()), Error);   // another format
  q = p;
  q.threads = 1;  // threads never change the samples: the same set
  EXPECT_NO_THROW(tiles::TileSet(q, 128, tiles::TileFormat::png16, dir.string()));
  fs::remove_all(dir);
}

// The CLI end to end: gdalinfo opens the mosaic as one raster of the whole's
// size with overviews and the 16-bit scale; a rerun skips every tile.
TEST(Tiles, CliWritesAMosaicThatGdalinfoOpens) {
  const fs::path dir = fresh_dir("cli");
  const std::string cmd = std::string(FT_CLI_PATH) + " tiles --levels 10 --hurst 0.7 --seed 5 --tile 256 --quiet --out " +
                          dir.string();
  std::string out = run(cmd);
  ASSERT_EQ(out.rfind("FAILED", 0), std::string::npos) << out;
  EXPECT_EQ(nlohmann::json::parse(out)["written"], 16);
  const nlohmann::json info = nlohmann::json::parse(run("gdalinfo -json " + (dir / "mosaic.vrt").string()));
  EXPECT_EQ(info["size"], nlohmann::json::array({1025, 1025}));
  const nlohmann::json& band = info["bands"][0];
  EXPECT_EQ(band["type"], "UInt16");
  EXPECT_EQ(band["overviews"].size(), 2u);  // 513 and 257 samples a side
  const nlohmann::json m = *tiles::read_manifest(dir.string());
  EXPECT_NEAR(band["offset"].get<double>(), m["height_range"]["min"].get<double>(), 1e-9);
  EXPECT_TRUE(m["complete"].get<bool>());
  // The mosaic's pixels are the tiles' pixels (GDAL reads the raw 16-bit
  // values: the band's offset and scale give heights).
  const Heightfield whole = io::read_heightfield((dir / "mosaic.vrt").string());
  const GrayImage tile = io::read_png((dir / "tile_r001_c002.png").string());
  ASSERT_EQ(whole.width(), 1025);
  for (int k = 0; k < 257; k += 16) {
    EXPECT_EQ(whole.at(512 + k, 256 + 9), float(tile.pixels[size_t(9) * 257 + size_t(k)]));
    EXPECT_EQ(whole.at(512 + 9, 256 + k), float(tile.pixels[size_t(k) * 257 + 9]));
  }
  out = run(cmd);
  EXPECT_EQ(nlohmann::json::parse(out)["skipped"], 16) << out;
  // Another seed into the same folder is refused with a message.
  out = run(std::string(FT_CLI_PATH) + " tiles --levels 10 --hurst 0.7 --seed 6 --tile 256 --out " + dir.string());
  EXPECT_NE(out.find("holds another tile set (seed: 6 here, 5 in the folder)"), std::string::npos) << out;
  fs::remove_all(dir);
}

TEST(Tiles, SpectralIsRefused) {
  ft_terrain_params p = terrain::default_terrain_params();
  p.method = FT_TERRAIN_SPECTRAL;
  EXPECT_THROW(tiles::TileSet(p, 128, tiles::TileFormat::png16, fresh_dir("spectral").string()), Error);
}

// H and D of a tile set from per-tile increment sums equal the in-memory
// estimate of the whole (analysis/increment_sums.hpp): same lags, every
// aligned pair counted once, only the order of the additions differs.
TEST(Tiles, HurstFromTileSumsEqualsTheWhole) {
  const ft_terrain_params p = midpoint(10, 21);  // 1025^2; default lags 1..64
  const Heightfield whole = terrain::generate_terrain(p);
  for (analysis::HurstMethod m : {analysis::HurstMethod::kVariogramAligned, analysis::HurstMethod::kMadogramAligned}) {
    analysis::HurstOptions o;
    o.method = m;
    const analysis::HurstEstimate direct = analysis::estimate_hurst_surface(whole, o);
    const std::vector<int64_t> lags = analysis::surface_lags(o, 1025, 1025);
    ASSERT_EQ(lags.back(), 64);
    const tiles::TileGrid g = tiles::make_tile_grid(1025, 1025, 128);
    std::vector<double> sum(lags.size(), 0.0), count(lags.size(), 0.0);
    for (int32_t row = 0; row < g.rows(); ++row)
      for (int32_t col = 0; col < g.columns(); ++col) {
        const terrain::Window w = g.window(col, row);
        const Heightfield t = terrain::generate_terrain_window(p, 0, w.x0, w.y0, w.width, w.height);
        analysis::add_window_increments(t, m, w.x0, w.y0, 1025, 1025, lags, sum.data(), count.data());
      }
    // Pairs at lag 1: 2 x 1025 x 1024 (rows and columns), each once.
    EXPECT_EQ(count[0], 2.0 * 1025 * 1024);
    const analysis::HurstEstimate tiled = analysis::estimate_from_increments(m, lags, sum.data(), count.data());
    EXPECT_NEAR(tiled.hurst, direct.hurst, 1e-12);
    EXPECT_NEAR(tiled.dimension, 3.0 - direct.hurst, 1e-12);
    EXPECT_NEAR(tiled.hurst, 0.7, 0.05);  // and it is the terrain's H (a sanity bound, not the test)
  }
  analysis::HurstOptions plain;
  plain.method = analysis::HurstMethod::kVariogram;
  EXPECT_THROW(analysis::surface_lags(plain, 1025, 1025), Error);
  // A lag longer than the tile leaves it: refused.
  Heightfield t = terrain::generate_terrain_window(p, 0, 0, 0, 33, 33);
  std::vector<double> s(8, 0.0), c(8, 0.0);
  EXPECT_THROW(analysis::add_window_increments(t, analysis::HurstMethod::kVariogramAligned, 0, 0, 1025, 1025, {64}, s.data(), c.data()),
               Error);
}

// A window read back from the tile files at a level of detail is the
// coarser stage of a midpoint terrain: exact from float32 GeoTIFF tiles,
// within half a 16-bit step from PNG tiles; it spans several tiles.
TEST(Tiles, WindowReadBackAtLodIsTheCoarserStage) {
  const ft_terrain_params p = midpoint(9, 13);  // 513^2 in 4 x 4 tiles of 129^2
  for (tiles::TileFormat f : {tiles::TileFormat::tiff, tiles::TileFormat::png16}) {
    const fs::path dir = fresh_dir(std::string("read_") + tiles::format_name(f));
    tiles::TileSet set(p, 128, f, dir.string());
    write_all(set, p);
    set.finish();
    int64_t ew = 0, eh = 0;
    tiles::tileset_extent(dir.string(), 2, &ew, &eh);
    EXPECT_EQ(ew, 129);
    for (int lod : {0, 2}) {
      const int64_t x0 = lod ? 5 : 100, y0 = lod ? 17 : 120;  // across tile edges at both lods
      const int32_t w = lod ? 90 : 200, h = lod ? 70 : 150;
      const Heightfield got = tiles::read_tileset_window(dir.string(), lod, x0, y0, w, h);
      const Heightfield want = terrain::generate_terrain_window(p, lod, x0, y0, w, h);
      const double tol = f == tiles::TileFormat::tiff ? 0.0 : 0.5 * (set.spec().height_max - set.spec().height_min) / 65535 + 1e-6;
      double worst = 0;
      for (int32_t j = 0; j < h; ++j)
        for (int32_t i = 0; i < w; ++i) worst = std::max(worst, std::fabs(double(got.at(i, j)) - want.at(i, j)));
      EXPECT_LE(worst, tol) << tiles::format_name(f) << " lod " << lod;
      EXPECT_DOUBLE_EQ(got.world_size(), set.spec().spacing * (1 << lod) * (w - 1));
    }
    EXPECT_THROW(tiles::read_tileset_window(dir.string(), 2, 100, 0, 30, 1), Error);  // past the extent
    // A damaged tile is named, not read.
    fs::remove(dir / tiles::tile_file_name(set.spec(), 1, 1));
    EXPECT_THROW(tiles::read_tileset_window(dir.string(), 0, 120, 120, 20, 20), Error);
    fs::remove_all(dir);
  }
}
