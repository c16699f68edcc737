// manifest.json of a tile set: what terrain it is (every parameter the
// method uses, the reference grid's CRC), how it is cut, its height range
// and world size, and each finished tile's CRC-32. It is rewritten (atomically)
// after every tile, so a killed run leaves the record of what is complete.
// The "identity" part (terrain, tile size, format) decides whether a folder
// may be resumed: another terrain's folder is refused, never mixed.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "terrain/terrain.hpp"  // ft_terrain_params

namespace ft {

inline constexpr const char* kManifestName = "manifest.json";

// The parameters that define the terrain's samples, as JSON: the fields the
// method uses (not threads or callbacks), enums by name, the reference grid
// as its size and the CRC-32 of its float32 values.
nlohmann::json terrain_identity(const ft_terrain_params& p);

// The manifest in `dir`, or nothing when there is none; throws FT_ERR_IO for
// one that cannot be parsed.
std::optional<nlohmann::json> read_manifest(const std::string& dir);
void write_manifest(const std::string& dir, const nlohmann::json& m);

// "" when `existing` describes the same tile set as `wanted` (same identity),
// else the first difference in words ("hurst: 0.8 here, 0.7 in the folder").
std::string identity_difference(const nlohmann::json& wanted, const nlohmann::json& existing);

}  // namespace ft
