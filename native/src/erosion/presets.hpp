// SPDX-License-Identifier: GPL-3.0-or-later
// Named erosion recipes (for `fracterra terrain --erode PRESET` and the
// add-on), and writing the maps to a folder.
#pragma once

#include <string>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {

// A preset: its id, the label an artist reads, the id it had before the
// landscape model (an alias that keeps old scripts running; empty if none),
// and what it makes.
struct ErosionPreset {
  std::string id, label, alias, description;
};
std::vector<ErosionPreset> erosion_presets();

// The preset by id, label or old id (case, spaces and hyphens ignored):
// a run of the landscape model in world units and years. Throws naming the
// known presets.
ErosionConfig erosion_preset(const std::string& name);
// Every preset's id (tests run each).
std::vector<std::string> erosion_preset_names();
// The one entry the terrain pipeline and the CLI call. The presets need no
// fitting any more (world units and years), so this is erosion_preset(name);
// `terrain` stays for the callers and for fits to come.
ErosionConfig erosion_preset(const std::string& name, const Heightfield& terrain);

// The six maps as 16-bit PNGs in `dir` (drainage_area.png, slope.png, ...),
// each with its real range recorded in the PNG, and maps.json listing file,
// min, max, unit and scale of each. Drainage area is written as log10(area)
// (scale "log10", its encoded range in encoded_min / encoded_max): a linear
// 16-bit step would be several cells on a large terrain. With
// `float_format` ".tif" or ".exr" every map is also written as float32 with
// its linear values (float_file in maps.json). Every file is written
// atomically.
void write_erosion_maps(const ErosionMaps& maps, const std::string& dir, const std::string& float_format = "");
// One map of such a folder with its linear values: the float file when
// maps.json lists one, else the PNG (10^v for a log10 map). `name` is a
// key of maps.json ("deposited", "drainage_area", ...).
Heightfield read_erosion_map(const std::string& dir, const std::string& name);

}  // namespace ft::erosion
