// Named erosion recipes (for `fracterra terrain --erode PRESET` and the
// add-on), and writing the maps to a folder.
#pragma once

#include <string>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {

// "valleys": fluvial only; "rain": hydraulic only; "scree": thermal only;
// "land": all three. Throws naming the known presets.
ErosionConfig erosion_preset(const std::string& name);
std::vector<std::string> erosion_preset_names();

// The six maps as 16-bit PNGs in `dir` (drainage_area.png, slope.png, ...),
// each with its real range recorded in the PNG, and maps.json listing file,
// min, max and unit of each. Every file is written atomically.
void write_erosion_maps(const ErosionMaps& maps, const std::string& dir);

}  // namespace ft::erosion
