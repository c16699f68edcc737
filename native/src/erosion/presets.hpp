// Named erosion recipes (for `fracterra terrain --erode PRESET` and the
// add-on), and writing the maps to a folder.
#pragma once

#include <string>
#include <vector>

#include "erosion/erosion.hpp"

namespace ft::erosion {

// "valleys": fluvial only; "rain": hydraulic only; "scree": thermal only;
// "land": all three. Throws naming the known presets. The uplift of
// "valleys" and "land" here is a fixed 1e-4 world units/yr (what
// ft_erosion_preset gives): right for a terrain about 6 units high only.
ErosionConfig erosion_preset(const std::string& name);
// Every preset's name (tests run each).
std::vector<std::string> erosion_preset_names();
// The same preset fitted to `terrain` (the CLI's erode --preset and
// terrain --erode): the uplift of "valleys" and "land" becomes the rate that
// would raise the land by `terrain`'s relief (max - min) over the preset's
// fluvial run (steps x dt years). Incision balances it, so the eroded land
// keeps about the input's relief, with graded channels. The fixed 1e-4
// units/yr lifts 6 units over that run, which on a default terrain (10
// units across, relief about 1) leaves ridges 5 units high.
ErosionConfig erosion_preset(const std::string& name, const Heightfield& terrain);

// The six maps as 16-bit PNGs in `dir` (drainage_area.png, slope.png, ...),
// each with its real range recorded in the PNG, and maps.json listing file,
// min, max and unit of each. Every file is written atomically.
void write_erosion_maps(const ErosionMaps& maps, const std::string& dir);

}  // namespace ft::erosion
