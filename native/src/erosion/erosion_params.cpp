// SPDX-License-Identifier: GPL-3.0-or-later
#include "erosion/erosion_params.hpp"

#include <cfloat>
#include <type_traits>

namespace ft::erosion {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;
constexpr uint32_t kAbi212 = 0x2000C;  // uplift_follows_terrain
constexpr uint32_t kAbi214 = 0x2000E;  // the landscape model and its maps
constexpr uint32_t kAbi221 = 0x20015;  // the sea
constexpr uint32_t kAbi228 = 0x2001C;  // scree_years
constexpr double kMaxRainPassValue = 1e6;
// The defaults are written once, in ErosionConfig's parts (erosion.hpp), and
// read here; the test ErosionParams.TableDefaultsAreTheConfigDefaults holds
// the rest (the sea, periodic) to ErosionConfig's.
constexpr FluvialConfig kFluvial{};
constexpr HydraulicConfig kHydraulic{};
constexpr ThermalConfig kThermal{};
constexpr ModelConfig kModel{};

#define ROW(field, type) FT_PARAM_ROW(ft_erosion_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_erosion_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_erosion_params), set by ft_erosion_params_init", .methods = kAll},
    {ROW(fluvial_steps, FT_PARAM_INT32), .element_kind = -1, .default_value = kFluvial.steps, .hard_min = 0,
     .hard_max = kMaxErosionSteps, .soft_min = 0, .soft_max = 200, .unit = "steps", .label = "Extra River Steps",
     .doc = "Expert: extra time steps of river incision after the run, in grid steps (so a finer grid "
            "changes more): stream power dz/dt = U - K A^m S with hillslope diffusion, solved implicitly "
            "(Braun & Willett 2013); 0: off (the presets use Duration instead)",
     .methods = kAll},
    {ROW(fluvial_dt, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .element_kind = -1,
     .default_value = kFluvial.dt, .hard_min = 0, .hard_max = DBL_MAX, .soft_min = 100, .soft_max = 10000,
     .unit = "years", .label = "Extra Step Length", .doc = "Years per extra river step", .methods = kAll},
    {ROW(erodibility, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kFluvial.erodibility, .hard_min = 0,
     .hard_max = DBL_MAX, .soft_min = 0, .soft_max = 2e-3, .unit = "1/yr", .label = "Rock Softness",
     .doc = "How fast running water cuts rock: the erodibility K of the stream-power law "
            "dz/dt = -K Q^m S (Q: water from upstream, world units^3/yr; S: slope)", .methods = kAll},
    {ROW(area_exponent, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kFluvial.area_exponent, .hard_min = 0,
     .hard_max = 2, .soft_min = 0.3, .soft_max = 0.7, .unit = "", .label = "River Concavity",
     .doc = "How much more a big river cuts than a small one: m in K Q^m S (slope exponent n = 1); "
            "the concavity of graded river profiles is m / n", .methods = kAll},
    // Label "Diffusion", not "Hillslope Diffusion": Blender's narrow sidebar cut the longer one.
    {ROW(diffusion, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kFluvial.diffusion, .hard_min = 0,
     .hard_max = DBL_MAX, .soft_min = 0, .soft_max = 1e-5, .unit = "world units^2/yr", .label = "Slope Softening",
     .doc = "Soil creep that rounds ridges and hillslopes: diffusivity D in dz/dt = D laplacian(z), implicit; "
            "0: none", .methods = kAll},
    {ROW(uplift, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kFluvial.uplift, .hard_min = 0,
     .hard_max = DBL_MAX, .soft_min = 0, .soft_max = 1e-3, .unit = "world units/yr", .label = "Extra Uplift",
     .doc = "Expert, extra river steps only: uplift rate U of every cell; bounded edges erode towards the "
            "lowest input height", .methods = kAll},
    {ROW(hydraulic_iterations, FT_PARAM_INT32), .element_kind = -1, .default_value = kHydraulic.iterations,
     .hard_min = 0,
     .hard_max = kMaxErosionSteps, .soft_min = 0, .soft_max = 300, .unit = "passes", .label = "Extra Rain Passes",
     .doc = "Expert: water-flow passes after the run, in grid steps (so a finer grid changes less): water, "
            "sediment capacity, erosion, deposition, evaporation on the grid (virtual pipes, Mei, Decaudin & "
            "Hu 2007); 0: off",
     .methods = kAll},
    {ROW(hydraulic_dt, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kHydraulic.dt, .hard_min = 1e-6,
     .hard_max = 1, .soft_min = 0.005, .soft_max = 0.05, .unit = "seconds", .label = "Rain Pass Length",
     .doc = "Seconds per extra rain pass", .methods = kAll},
    // Rain and Water Load end at 1e6: the rain passes compute in float, where
    // a larger value (the fuzzer's capacity of 1.6e270) became inf and the
    // heights NaN; far below that, every pass already fills and cuts at its
    // limits (max_erosion).
    {ROW(rain, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kHydraulic.rain, .hard_min = 0,
     .hard_max = kMaxRainPassValue, .soft_min = 0, .soft_max = 0.05, .unit = "world units", .label = "Rain per Pass",
     .doc = "Water depth added to every cell per extra rain pass", .methods = kAll},
    {ROW(evaporation, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kHydraulic.evaporation, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 0.2, .unit = "", .label = "Evaporation",
     .doc = "Fraction of the water evaporated per extra rain pass", .methods = kAll},
    {ROW(capacity, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kHydraulic.capacity, .hard_min = 0,
     .hard_max = kMaxRainPassValue, .soft_min = 0, .soft_max = 5, .unit = "", .label = "Water Load",
     .doc = "How much sediment the rain passes' water carries: capacity constant Kc in C = Kc sin(tilt) |v|", .methods = kAll},
    {ROW(dissolve, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kHydraulic.dissolve, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Pickup",
     .doc = "Fraction of the capacity deficit taken from the bed per extra rain pass", .methods = kAll},
    {ROW(deposit, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kHydraulic.deposit, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Drop",
     .doc = "Fraction of the sediment above capacity laid down per extra rain pass", .methods = kAll},
    {ROW(thermal_iterations, FT_PARAM_INT32), .element_kind = -1, .default_value = kThermal.iterations, .hard_min = 0,
     .hard_max = kMaxErosionSteps, .soft_min = 0, .soft_max = 100, .unit = "passes", .label = "Extra Scree",
     .doc = "Expert: scree passes after the run, in grid steps: material above the talus angle slides down "
            "(thermal erosion, Musgrave, Kolb & Mace 1989); 0: off",
     .methods = kAll},
    {ROW(talus_degrees, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = kThermal.talus_degrees, .hard_min = 0,
     .hard_max = 89, .soft_min = 20, .soft_max = 45, .unit = "degrees", .label = "Scree Angle",
     .doc = "Angle of repose (talus): steeper slopes shed material, which runs down as scree", .methods = kAll},
    {ROW(thermal_rate, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .element_kind = -1,
     .default_value = kThermal.rate, .hard_min = 0, .hard_max = 1, .soft_min = 0.1, .soft_max = 1, .unit = "",
     .label = "Scree Rate", .doc = "Fraction of the excess over the talus slope moved per extra scree pass", .methods = kAll},
    {ROW(periodic, FT_PARAM_BOOL), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Tiles",
     .doc = "The terrain tiles: eroded as a torus, it stays seamless", .methods = kAll},
    threads_row<ft_erosion_params>(),
    progress_row<ft_erosion_params>("Called as erosion advances; may cancel; NULL: none"),
    progress_user_row<ft_erosion_params>(),
    {ROW(uplift_follows_terrain, FT_PARAM_BOOL), .since = kAbi212, .element_kind = -1,
     .default_value = double(kFluvial.uplift_follows_terrain), .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Uplift Follows Land",
     .doc = "Each cell rises at Uplift x its input height above the lowest over the input's relief, so a "
            "landform keeps its shape (a plain at the lowest height stays); off: every cell at the Uplift rate",
     .methods = kAll},
    {ROW(strength, FT_PARAM_DOUBLE), .since = kAbi214, .element_kind = -1, .default_value = kModel.strength,
     .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Strength",
     .doc = "How far the erosion goes: the run lasts Strength x Duration. 0.5 keeps the landform's shape and "
            "height; 1 wears it further",
     .methods = kAll},
    {ROW(duration, FT_PARAM_DOUBLE), .since = kAbi214, .element_kind = -1, .default_value = kModel.duration,
     .hard_min = 0, .hard_max = 1e9, .soft_min = 0, .soft_max = 1e6, .unit = "years", .label = "Duration",
     .doc = "Years of weathering at Strength 1: rivers cut channels (stream power, Braun & Willett 2013), "
            "steep slopes shed scree, the sediment settles in fans and valley floors (Yuan et al. 2019), soil "
            "creeps. The same terrain at any resolution erodes alike. 0: off",
     .methods = kAll},
    {ROW(deposition, FT_PARAM_DOUBLE), .since = kAbi214, .element_kind = -1, .default_value = kModel.deposition,
     .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Fan Building",
     .doc = "How readily rivers drop what they carry: 0 carves and carries everything away, 1 fills valleys "
            "and lakes and builds wide fans (G in dz/dt = -K Q^m S + G Qs / Q, Yuan et al. 2019; a lake "
            "keeps G of what reaches it, as a flat floor)",
     .methods = kAll},
    {ROW(rainfall, FT_PARAM_DOUBLE), .since = kAbi214, .element_kind = -1, .default_value = kModel.rainfall,
     .hard_min = 0, .hard_max = 1e6, .soft_min = 0, .soft_max = 4, .unit = "world units/yr", .label = "Rainfall",
     .doc = "Water falling on every cell per year (x the rain map); more water cuts faster", .methods = kAll},
    {ROW(erosion_mask, FT_PARAM_POINTER), .flags = kData, .since = kAbi214, .element_type = FT_PARAM_FLOAT,
     .element_kind = -1, .unit = "", .label = "Erosion Mask",
     .doc = "Where erosion acts: width x height values in [0, 1], row-major, corner to corner, resampled "
            "bilinearly (0: untouched, though sediment may settle there); NULL: everywhere",
     .methods = kAll},
    {ROW(erosion_mask_width, FT_PARAM_INT32), .flags = kData, .since = kAbi214, .element_kind = -1,
     .default_value = 0, .hard_min = 0, .hard_max = kMaxMapSide, .unit = "samples", .label = "Erosion Mask Width",
     .doc = "Columns of the erosion mask, 2..65536 with a mask", .methods = kAll},
    {ROW(erosion_mask_height, FT_PARAM_INT32), .flags = kData, .since = kAbi214, .element_kind = -1,
     .default_value = 0, .hard_min = 0, .hard_max = kMaxMapSide, .unit = "samples", .label = "Erosion Mask Height",
     .doc = "Rows of the erosion mask, 2..65536 with a mask", .methods = kAll},
    {ROW(rain_map, FT_PARAM_POINTER), .flags = kData, .since = kAbi214, .element_type = FT_PARAM_FLOAT,
     .element_kind = -1, .unit = "", .label = "Rain Map",
     .doc = "Where rain falls: width x height values in [0, 1] (x Rainfall), row-major, corner to corner, "
            "resampled bilinearly; NULL: everywhere",
     .methods = kAll},
    {ROW(rain_map_width, FT_PARAM_INT32), .flags = kData, .since = kAbi214, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = kMaxMapSide, .unit = "samples", .label = "Rain Map Width",
     .doc = "Columns of the rain map, 2..65536 with a map", .methods = kAll},
    {ROW(rain_map_height, FT_PARAM_INT32), .flags = kData, .since = kAbi214, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = kMaxMapSide, .unit = "samples", .label = "Rain Map Height",
     .doc = "Rows of the rain map, 2..65536 with a map", .methods = kAll},
    {ROW(sea, FT_PARAM_ENUM), .since = kAbi221, .element_kind = -1, .default_value = int32_t(Sea::kNone),
     .hard_min = int32_t(Sea::kNone), .hard_max = int32_t(Sea::kFraction), .soft_min = int32_t(Sea::kNone),
     .soft_max = int32_t(Sea::kFraction), .unit = "", .label = "Sea",
     .doc = "The sea is a base level like the map's edge: rivers end there and cut no lower, the sediment they "
            "bring is carried away and the sea floor stays as it is (none, below a height, or below a fraction "
            "of the samples; every cell at or below it, so a landform's inland sea stays water too)",
     .methods = kAll, .enum_count = 3, .enum_items = kSeaItems},
    {ROW(sea_level, FT_PARAM_DOUBLE), .since = kAbi221, .element_kind = -1, .default_value = 0,
     .hard_min = -kMaxErosionHeight, .hard_max = kMaxErosionHeight, .soft_min = -100, .soft_max = 100,
     .unit = "world units", .label = "Sea Level", .doc = "Height of the sea (sea 'height')", .methods = kAll},
    {ROW(sea_fraction, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MAX_EXCLUSIVE, .since = kAbi221, .element_kind = -1,
     .default_value = 0.3, .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 0.95, .unit = "",
     .label = "Sea Fraction", .doc = "Share of the samples under the sea (sea 'fraction')", .methods = kAll},
    {ROW(scree_years, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE, .since = kAbi228, .element_kind = -1,
     .default_value = kModel.scree_years, .hard_min = 0, .hard_max = 1e12, .soft_min = 1e3, .soft_max = 1e6,
     .unit = "years", .label = "Scree Time",
     .doc = "How long steep slopes take to shed down to the scree angle: the excess of a slope over it sheds "
            "with this e-folding time; shorter than the run (Strength x Duration) wears every steep slope back "
            "to the angle, longer only the cliffs' edges",
     .methods = kAll},
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& erosion_param_table() {
  static const ParamTable table{"ft_erosion_params", sizeof(ft_erosion_params), kRows};
  return table;
}

// Every field of ft_erosion_params beside the ErosionConfig field it stands
// for, once, for both directions: f(struct_field, config_field). (The
// config's min_tilt and max_erosion have no field and keep their defaults;
// the progress callback is wrapped by from_c.)
template <class Params, class Config, class F>
void for_each_field_pair(Params& p, Config& c, F f) {
  f(p.strength, c.model.strength);
  f(p.duration, c.model.duration);
  f(p.deposition, c.model.deposition);
  f(p.rainfall, c.model.rainfall);
  f(p.scree_years, c.model.scree_years);
  f(p.erosion_mask, c.erosion_mask.values);
  f(p.erosion_mask_width, c.erosion_mask.width);
  f(p.erosion_mask_height, c.erosion_mask.height);
  f(p.rain_map, c.rain_map.values);
  f(p.rain_map_width, c.rain_map.width);
  f(p.rain_map_height, c.rain_map.height);
  f(p.fluvial_steps, c.fluvial.steps);
  f(p.fluvial_dt, c.fluvial.dt);
  f(p.erodibility, c.fluvial.erodibility);
  f(p.area_exponent, c.fluvial.area_exponent);
  f(p.diffusion, c.fluvial.diffusion);
  f(p.uplift, c.fluvial.uplift);
  f(p.uplift_follows_terrain, c.fluvial.uplift_follows_terrain);
  f(p.hydraulic_iterations, c.hydraulic.iterations);
  f(p.hydraulic_dt, c.hydraulic.dt);
  f(p.rain, c.hydraulic.rain);
  f(p.evaporation, c.hydraulic.evaporation);
  f(p.capacity, c.hydraulic.capacity);
  f(p.dissolve, c.hydraulic.dissolve);
  f(p.deposit, c.hydraulic.deposit);
  f(p.thermal_iterations, c.thermal.iterations);
  f(p.talus_degrees, c.thermal.talus_degrees);
  f(p.thermal_rate, c.thermal.rate);
  f(p.sea, c.sea);
  f(p.sea_level, c.sea_level);
  f(p.sea_fraction, c.sea_fraction);
  f(p.periodic, c.periodic);
  f(p.threads, c.threads);
}

ft_erosion_params to_c(const ErosionConfig& c) {
  ft_erosion_params p = defaults_of<ft_erosion_params>(erosion_param_table());
  for_each_field_pair(p, c, [](auto& to, const auto& from) { to = static_cast<std::decay_t<decltype(to)>>(from); });
  return p;
}

ErosionConfig from_c(const ft_erosion_params& given) {
  const ft_erosion_params p = upgraded(erosion_param_table(), given);
  check_ranges(erosion_param_table(), &p);
  ErosionConfig c;
  // (int32_t -> bool is `!= 0`.)
  for_each_field_pair(p, c, [](const auto& from, auto& to) { to = static_cast<std::decay_t<decltype(to)>>(from); });
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

}  // namespace ft::erosion
