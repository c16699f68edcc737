// SPDX-License-Identifier: GPL-3.0-or-later
// manifest.json of a tile set: what terrain it is (every parameter the
// method uses, the reference grid's CRC), how it is cut, its height range
// and world size, and each finished tile's CRC-32. Finished tiles are
// appended to a journal beside it (one line each, flushed to disk), which is
// folded into the manifest (rewritten atomically, then the journal removed)
// when a set is resumed and when it is finished: recording n tiles costs
// O(n), not n rewrites of an O(n) manifest, and a killed run still leaves
// the record of what is complete.
// The "identity" part (terrain, erosion, maps, tile size, format) decides
// whether a folder may be resumed: another terrain's folder is refused, never
// mixed.
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "terrain/terrain.hpp"  // ft_terrain_params
#include "tiles/tile_terrain.hpp"

namespace ft::tiles {

inline constexpr const char* kManifestName = "manifest.json";
inline constexpr const char* kJournalName = "manifest.journal";

// The parameters that define the terrain's samples, as JSON: the fields the
// method uses (not threads or callbacks), enums by name, the reference grid
// as its size and the CRC-32 of its float32 values.
nlohmann::json terrain_identity(const ft_terrain_params& p);
// The erosion a set's terrain gets, as JSON: the preset's name ("none") and
// the settings the pipeline erodes with (the preset over the given settings:
// every field but threads, periodic and callbacks; a mask or rain map as its
// size and CRC-32). Null for a set that is not eroded.
nlohmann::json erosion_identity(const TileTerrain& t);
// What makes a set this set: {"terrain", "tile", "tile_format"}, plus
// "erosion" for an eroded set and "maps" (the map names) for a set with maps.
nlohmann::json tileset_identity(const TileTerrain& t, int64_t tile, const std::string& format);

// A manifest's text (from `path`, named in messages): throws FT_ERR_IO when
// it is not JSON or lacks a field its readers take (the format, tile, width,
// height, columns, rows, terrain, sample_spacing, height_range, and columns x
// rows tiles with file, x0, y0 and crc32; with "maps", each tile's
// maps_crc32 null or one CRC-32 per map), naming what is wrong.
nlohmann::json parse_manifest(const std::string& text, const std::string& path);
// The manifest in `dir`, or nothing when there is none; throws FT_ERR_IO for
// one that parse_manifest refuses.
std::optional<nlohmann::json> read_manifest(const std::string& dir);
void write_manifest(const std::string& dir, const nlohmann::json& m);

// Appends {"column", "row", "crc32"} (and "maps_crc32" when `maps` is not
// null: one CRC-32 per map) as one line to the journal and flushes it to
// disk (FT_ERR_IO on failure).
void append_journal(const std::string& dir, int32_t col, int32_t row, uint32_t crc,
                    const std::array<uint32_t, FT_MAP_COUNT>* maps = nullptr);
// Sets the CRC-32 of m's tiles from the journal's complete lines (a torn
// last line, left by a crash while appending, is skipped: that tile is
// written again); returns how many lines were applied. No journal: 0.
int64_t replay_journal(const std::string& dir, nlohmann::json& m);
void remove_journal(const std::string& dir);

// "" when `existing` describes the same tile set as `wanted` (same identity),
// else the first difference in words ("hurst: 0.8 here, 0.7 in the folder",
// "erosion: preset land here, none in the folder", "erosion strength: 0.7
// here, 0.5 in the folder").
std::string identity_difference(const nlohmann::json& wanted, const nlohmann::json& existing);

}  // namespace ft::tiles
