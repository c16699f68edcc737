// fracterra tiles: a terrain too large for memory, written as a tile set
// (tiles sharing their edge samples, one height scale, manifest.json,
// mosaic.vrt with overviews). Resumable: a rerun skips the tiles whose
// CRC-32 matches the manifest. The distributed version of the same loop is
// the Dask driver (python3 -m fracterra.core.tiles; docs/scale.md).
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/cli_util.hpp"
#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "cli/path_checks.hpp"
#include "core/error.hpp"
#include "io/heightfield_io.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_params.hpp"
#include "tiles/tileset.hpp"

namespace ft::cli {
namespace {

struct TilesOptions {
  ft_terrain_params p = terrain::default_terrain_params();
  std::string reference, out, format = "png16";
  int64_t tile = 4096;
  bool quiet = false;
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
  const nlohmann::json j = {{"tiles", g.count()},          {"written", written},
                            {"skipped", skipped},          {"columns", g.columns()},
                            {"rows", g.rows()},            {"width", g.width},
                            {"height", g.height},          {"height_range", set.manifest()["height_range"]},
                            {"seconds", clock.seconds()}};
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
                    return [o] { return run(*o); };
                  },
                  12});

}  // namespace
}  // namespace ft::cli
