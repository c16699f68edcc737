// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/build_params.hpp"

#include <cctype>

namespace ft::pipeline {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;
constexpr uint32_t kAbi213 = 0x2000D;
constexpr uint32_t kAbi220 = 0x20014;

// The names are ft_erosion_preset's (lower case); PipelineTest checks them
// against erosion_preset_names().
constexpr ft_param_enum_item kPresets[] = {
    {FT_EROSION_PRESET_NONE, "NONE", "None", "No preset: the erosion settings as given (none: no erosion)"},
    {FT_EROSION_PRESET_VALLEYS, "VALLEYS", "Gentle Valleys", "Soft, long river valleys under rounded hills"},
    {FT_EROSION_PRESET_RAIN, "RAIN", "Alluvial Fans", "Valleys whose sediment spreads in fans where they open out"},
    {FT_EROSION_PRESET_SCREE, "SCREE", "Scree Slopes", "Steep slopes shed to their talus angle; little river work"},
    {FT_EROSION_PRESET_LAND, "LAND", "Rugged Mountains", "Incised valleys, sharp ridges and scree"},
    {FT_EROSION_PRESET_BADLANDS, "BADLANDS", "Badlands", "Dense gullies cut into soft rock"},
};

#define ROW(field, type) FT_PARAM_ROW(ft_build_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .since = kAbi213, .element_kind = -1,
     .default_value = sizeof(ft_build_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_build_params), set by ft_build_params_init", .methods = kAll},
    {ROW(threads, FT_PARAM_INT32), .since = kAbi213, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1024, .soft_min = 0, .soft_max = 64, .unit = "threads", .label = "Threads",
     .doc = "Worker threads of every stage, 0: all cores; the output never depends on it", .methods = kAll},
    {ROW(terrain, FT_PARAM_POINTER), .flags = kData, .since = kAbi213, .element_type = FT_PARAM_OPAQUE,
     .element_kind = FT_PARAMS_TERRAIN, .unit = "", .label = "Terrain",
     .doc = "The terrain and its landform (ft_terrain_params); required", .methods = kAll},
    {ROW(erosion, FT_PARAM_POINTER), .flags = kData, .since = kAbi213, .element_type = FT_PARAM_OPAQUE,
     .element_kind = FT_PARAMS_EROSION, .unit = "", .label = "Erosion",
     .doc = "The erosion settings (ft_erosion_params); NULL: no erosion unless a preset is named", .methods = kAll},
    {ROW(erosion_preset, FT_PARAM_ENUM), .since = kAbi213, .element_kind = -1,
     .default_value = FT_EROSION_PRESET_NONE, .hard_min = FT_EROSION_PRESET_NONE,
     .hard_max = FT_EROSION_PRESET_BADLANDS, .soft_min = FT_EROSION_PRESET_NONE,
     .soft_max = FT_EROSION_PRESET_BADLANDS,
     .unit = "", .label = "Erosion Preset",
     .doc = "Erode the generated terrain with a preset: it sets what it changes from the defaults (the "
            "landscape model's duration and rates); Strength and the other erosion settings stay as given",
     .methods = kAll, .enum_count = 6, .enum_items = kPresets},
    {ROW(progress, FT_PARAM_CALLBACK), .flags = kData, .since = kAbi213, .element_kind = -1, .unit = "",
     .label = "Progress", .doc = "Progress of all the stages together, 0..1; may cancel; NULL: none",
     .methods = kAll},
    {ROW(progress_user, FT_PARAM_POINTER), .flags = kData, .since = kAbi213, .element_type = FT_PARAM_OPAQUE,
     .element_kind = -1, .unit = "", .label = "Progress Data", .doc = "Passed to the progress callback",
     .methods = kAll},
    {ROW(rivers, FT_PARAM_POINTER), .flags = kData, .since = kAbi220, .element_type = FT_PARAM_OPAQUE,
     .element_kind = FT_PARAMS_HYDROLOGY, .unit = "", .label = "Rivers",
     .doc = "The rivers stage's settings (ft_hydrology_params) for ft_terrain_build_rivers; NULL: the defaults. "
            "A terrain that tiles gives rivers that wrap; a terrain's own sea is the rivers' sea",
     .methods = kAll},
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& build_param_table() {
  static const ParamTable table{"ft_build_params", sizeof(ft_build_params), kRows};
  return table;
}

std::string erosion_preset_name(int32_t preset) {
  if (preset == FT_EROSION_PRESET_NONE) return "";
  for (const ft_param_enum_item& item : kPresets)
    if (item.value == preset) {
      std::string name = item.name;
      for (char& c : name) c = char(std::tolower(static_cast<unsigned char>(c)));
      return name;
    }
  return "";  // out of range: refused by the table's range check before
}

}  // namespace ft::pipeline
