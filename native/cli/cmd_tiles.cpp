// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra tiles: a terrain too large for memory, written as a tile set
// (tiles sharing their edge samples, one height scale, manifest.json,
// mosaic.vrt with overviews), generated or built by the pipeline (landform,
// --erode, --maps) as `fracterra terrain` builds it. Resumable: a rerun
// skips the tiles whose CRC-32 matches the manifest. The distributed version of the same loop is
// the Dask driver (python3 -m fracterra.tiles; docs/scale.md). With
// --engine the finished set is also cut the way a game engine imports a
// large terrain in pieces (engines/engine_tiles.hpp), into OUT/<engine>/.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include <set>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/erosion_map_flags.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "core/platform.hpp"
#include "engines/engine_preset.hpp"
#include "engines/engine_tiles.hpp"
#include "erosion/erosion_params.hpp"
#include "io/heightfield_io.hpp"
#include "pipeline/build_params.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_params.hpp"
#include "tiles/tileset.hpp"

namespace ft::cli::cmd_tiles {
namespace {

// Erosion settings that are the terrain's, as for `fracterra terrain`: its
// threads, the torus of a terrain that tiles, its landform's sea.
const std::set<std::string> kTerrainsOwn = {"periodic", "threads", "sea", "sea_level", "sea_fraction"};

// What --engine on an eroded set without --maps says (python/fracterra/tiles.py says the same).
constexpr const char* kEngineWithoutMaps =
    "fracterra tiles: the engine tiles carry no splat maps: they come from the erosion maps (add --maps; each "
    "task then builds the whole terrain, since the drainage area is global)";

struct TilesOptions {
  ft_terrain_params p = terrain::default_terrain_params();
  ft_build_params build = defaults_of<ft_build_params>(pipeline::build_param_table());
  ft_erosion_params erosion = defaults_of<ft_erosion_params>(erosion::erosion_param_table());
  bool erosion_given = false;  // an erosion flag was given: erode with these settings
  ErosionMapFlags erosion_maps;
  std::string reference, falloff_mask, out, format = "png16";
  int64_t tile = 4096;
  bool quiet = false, maps = false;
  std::string engine;  // "" when not given
  int32_t engine_size = 0, region_size = engines::kGodotDefaultRegion;
};

int run(TilesOptions& o) {
  ft_terrain_params p = o.p;
  Heightfield reference, mask;
  if (!o.reference.empty()) {
    reference = io::read_heightfield(o.reference);
    if (reference.width() != reference.height())
      invalid("the reference grid '" + o.reference + "' must be square, 2^m + 1 per side");
    p.reference = reference.data();
    p.reference_size = reference.width();
  }
  if (!o.falloff_mask.empty()) {  // as `fracterra terrain --falloff-mask`
    mask = io::read_heightfield(o.falloff_mask);
    if (p.falloff != FT_FALLOFF_NONE && p.falloff != FT_FALLOFF_CUSTOM)
      invalid("--falloff-mask is the custom falloff's mask; it cannot go with --falloff " +
              std::string(p.falloff == FT_FALLOFF_SQUARE ? "square" : "radial"));
    p.falloff = FT_FALLOFF_CUSTOM;
    p.falloff_mask = mask.data();
    p.falloff_mask_width = mask.width();
    p.falloff_mask_height = mask.height();
  }
  o.erosion_maps.apply(o.erosion);  // --erosion-mask, --rain-map
  ft_build_params b = o.build;
  b.terrain = &p;
  b.erosion = o.erosion_given ? &o.erosion : nullptr;
  b.threads = p.threads;
  const tiles::TileTerrain t = tiles::TileTerrain::of(b, o.maps);
  if (!o.engine.empty() && t.erodes() && !t.maps)
    // The splat maps come from the erosion maps, whose drainage area is
    // global (each task builds the whole): without them a set of any size
    // is cut with its heights alone, in memory of a tile.
    std::fprintf(stderr, "%s\n", kEngineWithoutMaps);
  const engines::EngineOptions engine{o.engine.empty() ? engines::Engine::unity : engines::parse_engine(o.engine),
                                      o.region_size, o.engine_size};
  if (!o.engine.empty()) {  // a tile size the set cannot take is refused before anything is written
    int64_t width = 0, height = 0;
    terrain::terrain_extent(p, 0, &width, &height);
    engines::engine_tile_side(engine, width, height, o.tile);
  }
  Stopwatch clock;
  tiles::TileSet set(t, o.tile, tiles::parse_tile_format(o.format), o.out, true);
  const tiles::TileGrid& g = set.spec().grid;
  if (set.range_pending()) {
    // The exact range pass, tile by tile (an eroded set keeps what it builds for the writing pass).
    double lo = INFINITY, hi = -INFINITY;
    int64_t n = 0;
    for (int32_t row = 0; row < g.rows(); ++row)
      for (int32_t col = 0; col < g.columns(); ++col) {
        const tiles::HeightRange r = tiles::tile_height_range(t, set.spec(), set.dir(), col, row);
        lo = std::min(lo, r.min), hi = std::max(hi, r.max);
        if (!o.quiet) std::fprintf(stderr, "\rheight range: tile %lld of %lld", (long long)++n, (long long)g.count());
      }
    if (!o.quiet) std::fprintf(stderr, "\n");
    set.set_height_range(lo, hi);
  }
  int64_t written = 0, skipped = 0;
  for (int32_t row = 0; row < g.rows(); ++row)
    for (int32_t col = 0; col < g.columns(); ++col) {
      if (set.done(col, row)) {
        ++skipped;
        continue;
      }
      set.record(col, row, tiles::write_tile(t, set.spec(), set.dir(), col, row));
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
                    app.add_option("--falloff-mask", o->falloff_mask,
                                   "custom edge falloff (sets --falloff custom), as for fracterra terrain: a mask "
                                   "spanning the whole terrain, " + std::string(io::kHeightfieldReadHelp))
                        ->check(existing_file);
                    // The pipeline's and the erosion's settings, as `fracterra terrain`
                    // takes them: every tile is a window of what it builds.
                    add_param_flags(app, pipeline::build_param_table(), &o->build, {"threads"},
                                    {{"erosion_preset", "--erode"}});
                    add_param_flags(app, erosion::erosion_param_table(), &o->erosion, kTerrainsOwn);
                    o->erosion_maps.add_to(app);
                    app.add_flag("--maps", o->maps,
                                 "also write the terrain's maps (drainage area, slope, curvature, water depth, "
                                 "eroded, deposited) as float32 GeoTIFF tiles OUT/maps/MAP/tile_rRRR_cCCC.tif with "
                                 "a mosaic OUT/maps/MAP.vrt each");
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
                    return [o, &app] {
                      for (const ft_param_info& row : erosion::erosion_param_table().rows)
                        if (!kTerrainsOwn.count(row.name))
                          o->erosion_given = o->erosion_given || flag_given(app, row.name);
                      return run(*o);
                    };
                  },
                  12});

}  // namespace
}  // namespace ft::cli::cmd_tiles
