// SPDX-License-Identifier: GPL-3.0-or-later
#include "splat/splat_params.hpp"

#include <set>
#include <string>

#include "core/error.hpp"

namespace ft::splat {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kAbi219 = 0x20013;

#define ROW(field, type) FT_PARAM_ROW(ft_splat_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .since = kAbi219, .element_kind = -1,
     .default_value = sizeof(ft_splat_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_splat_params), set by ft_splat_params_init", .methods = kAll},
    {ROW(name, FT_PARAM_STRING), .since = kAbi219, .element_kind = -1, .unit = "", .label = "Name",
     .doc = "The layer's name (rock, grass, ...): unique within a rule set", .methods = kAll},
    {ROW(height_min, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Height Min",
     .doc = "Lower edge of the height band, as a fraction of the terrain's height range (0 lowest, 1 highest)",
     .methods = kAll},
    {ROW(height_max, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Height Max",
     .doc = "Upper edge of the height band (fraction of the height range)", .methods = kAll},
    {ROW(height_blend, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 0.3, .unit = "", .label = "Height Blend",
     .doc = "Width of the height band's soft edges, centred on them; 0: a hard edge", .methods = kAll},
    {ROW(slope_min, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 90, .soft_min = 0, .soft_max = 90, .unit = "degrees", .label = "Slope Min",
     .doc = "Lower edge of the slope band (the terrain's gradient, in its world units)", .methods = kAll},
    {ROW(slope_max, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 90, .hard_min = 0,
     .hard_max = 90, .soft_min = 0, .soft_max = 90, .unit = "degrees", .label = "Slope Max",
     .doc = "Upper edge of the slope band", .methods = kAll},
    {ROW(slope_blend, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 90, .soft_min = 0, .soft_max = 30, .unit = "degrees", .label = "Slope Blend",
     .doc = "Width of the slope band's soft edges; 0: a hard edge", .methods = kAll},
    {ROW(deposit_min, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 0.05, .unit = "", .label = "Deposit Min",
     .doc = "Deposited thickness (erosion map 'deposited') as a fraction of the height range at which the "
            "layer starts; 0: the layer does not look at deposits",
     .methods = kAll},
    {ROW(deposit_blend, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 0.05, .unit = "", .label = "Deposit Blend",
     .doc = "Width of the deposit condition's soft edge (fraction of the height range)", .methods = kAll},
    {ROW(flow_min, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 0.05, .unit = "", .label = "Flow Min",
     .doc = "Drainage area (erosion map 'drainage_area') as a fraction of the terrain's area at which the layer "
            "starts; 0: the layer does not look at flow",
     .methods = kAll},
    {ROW(flow_blend, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 10, .soft_min = 0, .soft_max = 3, .unit = "decades", .label = "Flow Blend",
     .doc = "Width of the flow condition's soft edge, in decades (factors of 10) of drainage area",
     .methods = kAll},
    {ROW(weight, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 1000, .soft_min = 0, .soft_max = 10, .unit = "", .label = "Weight",
     .doc = "The layer's strength against the others where several rules hold", .methods = kAll},
    {ROW(color, FT_PARAM_DOUBLE), .since = kAbi219, .element_kind = -1, .default_value = 0.5, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "sRGB", .label = "Color",
     .doc = "The layer's colour (red, green, blue in 0..1) in colour maps and materials", .methods = kAll},
};
FT_PARAM_TABLE_END
#undef ROW

std::string layer_label(const ft_splat_params& l, int32_t i) {
  return "splat layer " + std::to_string(i) + (l.name ? " ('" + std::string(l.name) + "')" : std::string());
}

}  // namespace

const ParamTable& splat_param_table() {
  static const ParamTable t{"ft_splat_params", sizeof(ft_splat_params), kRows};
  return t;
}

void validate_layers(const ft_splat_params* layers, int32_t count) {
  check_int_range("splat layer count", count, 1, kMaxLayers);
  check_not_null("splat layers", layers);
  std::set<std::string> names;
  for (int32_t i = 0; i < count; ++i) {
    const ft_splat_params l = upgraded(splat_param_table(), layers[i]);
    try {
      check_ranges(splat_param_table(), &l);
    } catch (const Error& e) {
      invalid(layer_label(layers[i], i) + ": " + e.what());
    }
    if (l.height_min > l.height_max)
      invalid(layer_label(l, i) + ": height_min " + format_number(l.height_min) + " is above height_max " +
              format_number(l.height_max));
    if (l.slope_min > l.slope_max)
      invalid(layer_label(l, i) + ": slope_min " + format_number(l.slope_min) + " is above slope_max " +
              format_number(l.slope_max));
    if (l.name && !names.insert(l.name).second)
      invalid("splat layers: the name '" + std::string(l.name) + "' is used twice (layers need unique names)");
  }
}

}  // namespace ft::splat
