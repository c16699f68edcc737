// fracterra tiles: a terrain too large for memory, written as a tile set
// (tiles sharing their edge samples, one height scale, manifest.json,
// mosaic.vrt with overviews). Resumable: a rerun skips the tiles whose
// CRC-32 matches the manifest. The distributed version of the same loop is
// the Dask driver (python3 -m fracterra.tiles; docs/scale.md). With
// --engine the finished set is also cut the way a game engine imports a
// large terrain in pieces (engines/engine_tiles.hpp), into OUT/<engine>/.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"
#include "engines/engine_preset.hpp"
#include "engines/engine_tiles.hpp"
#include "io/heightfield_io.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_params.hpp"
#include "tiles/tileset.hpp"

namespace ft::cli::cmd_tiles {
namespace {

struct TilesOptions {
  ft_terrain_params p = terrain::default_terrain_params();
  std::string reference, out, format = "png16";
  int64_t tile = 4096;
  bool quiet = false;
  std::string engine;  // "" when not given
  int32_t engine_size = 0, region_size = engines::kGodotDefaultRegion;
};

int run(const TilesOptions& o) {
  ft_terrain_params p = o.p;
  Heightfield reference;
  if (!o.reference.empty()) {
    reference = io::read_heightfield(o.reference);
    if (reference.width() != reference.height())
      invalid("the reference grid '" + o.reference + "' must be square, 2^m + 1 per side");
    p.reference = reference.data();
    p.reference_size = reference.width();
  }
  const engines::EngineOptions engine{o.engine.empty() ? engines::Engine::unity : engines::parse_engine(o.engine),
                                      o.region_size, o.engine_size};
  if (!o.engine.empty()) {  // a tile size the set cannot take is refused before anything is written
    int64_t width = 0, height = 0;
    terrain::terrain_extent(p, 0, &width, &height);
    engines::engine_tile_side(engine, width, height, o.tile);
  }
  Stopwatch clock;
  tiles::TileSet set(p, o.tile, tiles::parse_tile_format(o.format), o.out);
  const tiles::TileGrid& g = set.spec().grid;
  int64_t written = 0, skipped = 0;
  for (int32_t row = 0; row < g.rows(); ++row)
    for (int32_t col = 0; col < g.columns(); ++col) {
      if (set.done(col, row)) {
        ++skipped;
        continue;
      }
      set.record(col, row, tiles::write_tile(p, set.spec(), set.dir(), col, row));
      ++written;
      if (!o.quiet)
        std::fprintf(stderr, "\rtile %lld of %lld", (long long)(written + skipped), (long long)g.count());
    }
  if (!o.quiet && written) std::fprintf(stderr, "\n");
  set.finish();
  nlohmann::json j = {{"tiles", g.count()},          {"written", written},
                            {"skipped", skipped},          {"columns", g.columns()},
                            {"rows", g.rows()},            {"width", g.width},
                            {"height", g.height},          {"height_range", set.manifest()["height_range"]},
                            {"seconds", clock.seconds()}};
  if (!o.engine.empty()) {
    const std::string dir = platform::join_path(o.out, o.engine);
    const nlohmann::json side = engines::write_engine_tiles(o.out, dir, engine);
    j["engine"] = {{"folder", dir},
                   {"sidecar", platform::join_path(dir, o.engine + ".json")},
                   {"tile_samples", side["tile_samples"]},
                   {"columns", side["columns"]},
                   {"rows", side["rows"]}};
    j["seconds"] = clock.seconds();
  }
  std::printf("%s\n", j.dump().c_str());
  return 0;
}

Registration reg({"tiles", "Write a terrain larger than memory as a tile set (tiles, manifest, VRT mosaic)",
                  [](CLI::App& app) -> std::function<int()> {
                    auto o = std::make_shared<TilesOptions>();
                    add_param_flags(app, terrain::terrain_param_table(), &o->p);
                    app.add_option("--tile", o->tile,
                                   "cells per tile side: tiles hold tile + 1 samples and share their edge samples "
                                   "with their neighbours; range [2, 65536]")
                        ->capture_default_str();
                    app.add_option("--format", o->format,
                                   "png16: 16-bit PNG tiles with one height scale for all; tiff: float32 "
                                   "Cloud-Optimized GeoTIFF tiles")
                        ->capture_default_str();
                    app.add_option("--reference", o->reference,
                                   "reference grid (2^m + 1)^2 for midpoint/additions: " +
                                       std::string(io::kHeightfieldReadHelp))
                        ->check(existing_file);
                    app.add_option("--out", o->out,
                                   "the tile set's folder (created; a folder holding another tile set is refused; "
                                   "a rerun resumes)")
                        ->required();
                    app.add_flag("--quiet", o->quiet, "no progress line on stderr");
                    app.add_option("--engine", o->engine,
                                   "also cut the finished set for a game engine into OUT/ENGINE/ with "
                                   "OUT/ENGINE/ENGINE.json: unity (RAW16 tiles of 2^n + 1 sharing edges, "
                                   "NAME_X_Z.raw), unreal (16-bit PNG tiles, NAME_x0_y0.png), godot (Terrain3D "
                                   "regions as EXR) (docs/engines.md)")
                        ->check(CLI::IsMember({"unity", "unreal", "godot"}));
                    app.add_option("--engine-size", o->engine_size,
                                   "samples per engine tile side [default: the set's tiles (--tile + 1 for Unity, --tile for "
                                   "Unreal) when the engine takes them, else the largest that cuts the set, at most "
                                   "Unity 1025, Unreal 1024; Godot: the region size]");
                    app.add_option("--region-size", o->region_size,
                                   "--engine godot: Terrain3D's region size, 64..2048, a power of two")
                        ->capture_default_str();
                    return [o] { return run(*o); };
                  },
                  12});

}  // namespace
}  // namespace ft::cli::cmd_tiles
