// SPDX-License-Identifier: GPL-3.0-or-later
#include "hydrology/hydrology_params.hpp"

#include "erosion/erosion_params.hpp"

#include <cfloat>
#include <type_traits>

namespace ft::hydrology {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;
constexpr uint32_t kAbi215 = 0x2000F;
constexpr uint32_t kAbi227 = 0x2001B;  // min_depth
constexpr double kBig = 1e12;  // areas and heights: any sane world
static_assert(int32_t(Sea::kNone) == FT_WATER_SEA_NONE && int32_t(Sea::kHeight) == FT_WATER_SEA_HEIGHT &&
              int32_t(Sea::kFraction) == FT_WATER_SEA_FRACTION, "erosion's Sea is the C ABI's ft_water_sea");

// The defaults are HydrologyConfig's (hydrology.hpp); the test
// HydrologyParams.TableDefaultsAreTheConfigDefaults holds them together.
#define ROW(field, type) FT_PARAM_ROW(ft_hydrology_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .since = kAbi215, .element_kind = -1,
     .default_value = sizeof(ft_hydrology_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_hydrology_params), set by ft_hydrology_params_init", .methods = kAll},
    {ROW(min_area, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .since = kAbi215, .element_kind = -1,
     .default_value = 0.1, .hard_min = 0, .hard_max = kBig, .soft_min = 0.001, .soft_max = 10,
     .unit = "world units^2", .label = "Min Area",
     .doc = "Drainage area at which a river begins (its channel head)", .methods = kAll},
    {ROW(sea, FT_PARAM_ENUM), .since = kAbi215, .element_kind = -1, .default_value = FT_WATER_SEA_NONE,
     .hard_min = FT_WATER_SEA_NONE, .hard_max = FT_WATER_SEA_FRACTION, .soft_min = FT_WATER_SEA_NONE,
     .soft_max = FT_WATER_SEA_FRACTION, .unit = "", .label = "Sea",
     .doc = "Where the sea is: none (rivers end at the map's edge, in lakes or at sinks), below a height, or "
            "below a fraction of the samples; connected to the map's edge (an enclosed basin below it is a lake)",
     .methods = kAll,
     .enum_count = 3, .enum_items = erosion::kSeaItems},
    {ROW(sea_level, FT_PARAM_DOUBLE), .since = kAbi215, .element_kind = -1, .default_value = 0, .hard_min = -kBig,
     .hard_max = kBig, .soft_min = -100, .soft_max = 100, .unit = "world units", .label = "Sea Level",
     .doc = "Height of the sea (sea 'height'); must lie within the terrain's heights", .methods = kAll},
    {ROW(sea_fraction, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MAX_EXCLUSIVE, .since = kAbi215, .element_kind = -1,
     .default_value = 0.3, .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 0.95, .unit = "",
     .label = "Sea Fraction", .doc = "Share of the samples under the sea (sea 'fraction')", .methods = kAll},
    {ROW(min_lake_area, FT_PARAM_DOUBLE), .since = kAbi215, .element_kind = -1, .default_value = 0.01, .hard_min = 0,
     .hard_max = kBig, .soft_min = 0, .soft_max = 1, .unit = "world units^2", .label = "Min Lake Area",
     .doc = "Smaller filled depressions are not lakes: rivers run through them", .methods = kAll},
    {ROW(rain, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .since = kAbi215, .element_kind = -1,
     .default_value = 1, .hard_min = 0, .hard_max = kBig, .soft_min = 0.1, .soft_max = 10, .unit = "world units/yr",
     .label = "Rain", .doc = "Runoff per unit of area: discharge Q = drainage area x rain", .methods = kAll},
    {ROW(width_coefficient, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .since = kAbi215,
     .element_kind = -1, .default_value = 0.03, .hard_min = 0, .hard_max = kBig, .soft_min = 0.001, .soft_max = 0.2,
     .unit = "world units", .label = "Width Scale",
     .doc = "Width coefficient a in the width w = a Q^b of discharge Q (Leopold & Maddock 1953)", .methods = kAll},
    {ROW(width_exponent, FT_PARAM_DOUBLE), .since = kAbi215, .element_kind = -1, .default_value = 0.5, .hard_min = 0,
     .hard_max = 1, .soft_min = 0.3, .soft_max = 0.7, .unit = "", .label = "Width Growth",
     .doc = "Width exponent b in w = a Q^b: how fast rivers widen downstream (real rivers: about 0.5)",
     .methods = kAll},
    {ROW(depth_coefficient, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .since = kAbi215,
     .element_kind = -1, .default_value = 0.006, .hard_min = 0, .hard_max = kBig, .soft_min = 0.0001,
     .soft_max = 0.05, .unit = "world units", .label = "Depth Scale",
     .doc = "Depth coefficient c in the depth d = c Q^f of discharge Q", .methods = kAll},
    {ROW(depth_exponent, FT_PARAM_DOUBLE), .since = kAbi215, .element_kind = -1, .default_value = 0.4, .hard_min = 0,
     .hard_max = 1, .soft_min = 0.2, .soft_max = 0.6, .unit = "", .label = "Depth Growth",
     .doc = "Depth exponent f in d = c Q^f: how fast rivers deepen downstream (real rivers: about 0.4)",
     .methods = kAll},
    {ROW(smoothing, FT_PARAM_INT32), .since = kAbi215, .element_kind = -1, .default_value = 3, .hard_min = 0,
     .hard_max = 100, .soft_min = 0, .soft_max = 10, .unit = "passes", .label = "Smoothing",
     .doc = "Passes of smoothing that take the 8-direction grid steps out of the rivers (never uphill)",
     .methods = kAll},
    {ROW(meander_depth, FT_PARAM_INT32), .since = kAbi215, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 8, .soft_min = 0, .soft_max = 4, .unit = "levels", .label = "Meander Depth",
     .doc = "Levels of Nikulin's fractal polyline between vertices, sideways at most the river's width; 0: none",
     .methods = kAll},
    {ROW(meander_spread, FT_PARAM_DOUBLE), .since = kAbi215, .element_kind = -1, .default_value = 0.3,
     .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 0.5, .unit = "", .label = "Meander Spread",
     .doc = "The FPL's spread s (uniform displacement in [-s, s] of each segment's length)", .methods = kAll},
    {ROW(seed, FT_PARAM_UINT64), .since = kAbi215, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 18446744073709551615.0, .soft_min = 0, .soft_max = 1000, .unit = "", .label = "Seed",
     .doc = "Seed of the meanders", .methods = kAll},
    {ROW(tolerance, FT_PARAM_DOUBLE), .since = kAbi215, .element_kind = -1, .default_value = 1e-4, .hard_min = 0,
     .hard_max = kBig, .soft_min = 0, .soft_max = 0.01, .unit = "world units", .label = "Tolerance",
     .doc = "How far a smoothed or meandering vertex may lie above its upstream neighbour", .methods = kAll},
    {ROW(periodic, FT_PARAM_BOOL), .since = kAbi215, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Tiles",
     .doc = "The terrain tiles: rivers run across its edges (and drain to its lowest sample without a sea)",
     .methods = kAll},
    since(kAbi215, threads_row<ft_hydrology_params>()),
    {ROW(sinks, FT_PARAM_POINTER), .flags = kData, .since = kAbi215, .element_type = FT_PARAM_DOUBLE,
     .element_kind = -1, .unit = "world units", .label = "Sinks",
     .doc = "sink_count (x, y) points where water leaves the terrain (a swallow hole, a well); may be NULL",
     .methods = kAll},
    {ROW(sink_count, FT_PARAM_INT32), .flags = kData, .since = kAbi215, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = 1000000, .unit = "", .label = "Sink Count", .doc = "Number of sinks",
     .methods = kAll},
    since(kAbi215, progress_row<ft_hydrology_params>("Called as the rivers are traced; may cancel; NULL: none")),
    since(kAbi215, progress_user_row<ft_hydrology_params>()),
    {ROW(min_depth, FT_PARAM_DOUBLE), .since = kAbi227, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = kBig, .soft_min = 0, .soft_max = 1, .unit = "world units", .label = "Min Water Depth",
     .doc = "Water shallower than this is not shown, so none lies flush with the ground: a hollow no deeper "
            "is no lake, and a lake's shoreline runs where the ground lies this far under its level; 0: 1% of "
            "the terrain's relief",
     .methods = kAll},
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& hydrology_param_table() {
  static const ParamTable table{"ft_hydrology_params", sizeof(ft_hydrology_params), kRows};
  return table;
}

// Every field of ft_hydrology_params beside the HydrologyConfig field it
// stands for, once, for both directions: f(struct_field, config_field). The
// sinks (a pointer and a count against a vector) and the progress callback
// are converted by to_c and from_c.
template <class Params, class Config, class F>
void for_each_field_pair(Params& p, Config& c, F f) {
  f(p.min_area, c.min_area);
  f(p.sea, c.sea);
  f(p.sea_level, c.sea_level);
  f(p.sea_fraction, c.sea_fraction);
  f(p.min_lake_area, c.min_lake_area);
  f(p.rain, c.rain);
  f(p.width_coefficient, c.width_coefficient);
  f(p.width_exponent, c.width_exponent);
  f(p.depth_coefficient, c.depth_coefficient);
  f(p.depth_exponent, c.depth_exponent);
  f(p.smoothing, c.smoothing);
  f(p.meander_depth, c.meander_depth);
  f(p.meander_spread, c.meander_spread);
  f(p.seed, c.seed);
  f(p.tolerance, c.tolerance);
  f(p.periodic, c.periodic);
  f(p.threads, c.threads);
  f(p.min_depth, c.min_depth);
}

ft_hydrology_params to_c(const HydrologyConfig& c) {
  ft_hydrology_params p = defaults_of<ft_hydrology_params>(hydrology_param_table());
  for_each_field_pair(p, c, [](auto& to, const auto& from) { to = static_cast<std::decay_t<decltype(to)>>(from); });
  p.sinks = c.sinks.empty() ? nullptr : c.sinks.data();
  p.sink_count = int32_t(c.sinks.size() / 2);
  return p;
}

HydrologyConfig from_c(const ft_hydrology_params& given) {
  const ft_hydrology_params p = upgraded(hydrology_param_table(), given);
  check_ranges(hydrology_param_table(), &p);
  if (p.sink_count > 0 && !p.sinks) invalid("sinks is NULL but sink_count is " + std::to_string(p.sink_count));
  HydrologyConfig c;
  // (int32_t -> bool is `!= 0`; the sea's int32_t -> Sea is its enum value.)
  for_each_field_pair(p, c, [](const auto& from, auto& to) { to = static_cast<std::decay_t<decltype(to)>>(from); });
  if (p.sink_count > 0) c.sinks.assign(p.sinks, p.sinks + 2 * size_t(p.sink_count));
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

}  // namespace ft::hydrology
