// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/planet_params.hpp"

#include "core/error.hpp"
#include "noise/fbm.hpp"
#include "terrain/terrain_params.hpp"

namespace ft::planet {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint64_t kFbm = uint64_t(1) << FT_PLANET_FBM;  // the octave fields: midpoint has none
constexpr uint32_t kAbove = FT_PARAM_FLAG_MIN_EXCLUSIVE;
constexpr uint32_t kAbi218 = 0x20012;
constexpr double kBig = 1e12;

constexpr ft_param_enum_item kMethods[] = {
    {FT_PLANET_FBM, "FBM", "fBm", "Octave noise evaluated on the sphere in 3D (Quilez 2019, seed 004)"},
    {FT_PLANET_MIDPOINT, "MIDPOINT", "Midpoint",
     "Voss's midpoint displacement by subdivision of the cube-sphere (seed 000): detail to any level"},
};
constexpr ft_param_enum_item kSeas[] = {
    {FT_PLANET_SEA_NONE, "NONE", "None", "No sea"},
    {FT_PLANET_SEA_HEIGHT, "HEIGHT", "Height", "The sea is at a height above the radius"},
    {FT_PLANET_SEA_FRACTION, "FRACTION", "Fraction", "The sea covers a share of the planet's area"},
};

// The noise bases and variants are terrain.h's: their items are the terrain table's.
const ft_param_info& terrain_row(const char* name) { return *find_row(terrain::terrain_param_table(), name); }

#define ROW(field, type) FT_PARAM_ROW(ft_planet_params, field, type)
FT_PARAM_TABLE_BEGIN
// A function's static, not constexpr: the enum items come from the terrain table.
std::span<const ft_param_info> rows() {
  static const ft_param_info kRows[] = {
      {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .since = kAbi218, .element_kind = -1,
       .default_value = sizeof(ft_planet_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
       .label = "Struct Size", .doc = "sizeof(ft_planet_params), set by ft_planet_params_init", .methods = kAll},
      {ROW(method, FT_PARAM_ENUM), .since = kAbi218, .element_kind = -1, .default_value = FT_PLANET_FBM,
       .hard_min = FT_PLANET_FBM, .hard_max = FT_PLANET_MIDPOINT, .soft_min = FT_PLANET_FBM,
       .soft_max = FT_PLANET_MIDPOINT, .unit = "", .label = "Method", .doc = "How the planet is made",
       .methods = kAll, .enum_count = 2,
       .enum_items = kMethods},
      {ROW(radius, FT_PARAM_DOUBLE), .flags = kAbove, .since = kAbi218, .element_kind = -1,
       .default_value = 6371000, .hard_min = 0, .hard_max = kBig, .soft_min = 1000, .soft_max = 7e7,
       .unit = "metres", .label = "Radius", .doc = "The planet's radius (the Earth's: 6371000 m)", .methods = kAll},
      {ROW(sigma, FT_PARAM_DOUBLE), .flags = kAbove, .since = kAbi218, .element_kind = -1, .default_value = 4000,
       .hard_min = 0, .hard_max = kBig, .soft_min = 10, .soft_max = 20000, .unit = "metres",
       .label = "Height Scale",
       .doc = "Vertical scale: standard fBm heights lie within +-sigma; midpoint heights spread as much at H 0.8 "
              "(their corners' std and displacement scale are sigma / 5)",
       .methods = kAll},
      {ROW(hurst, FT_PARAM_DOUBLE), .since = kAbi218, .element_kind = -1, .default_value = 0.8, .hard_min = 0,
       .hard_max = 1, .soft_min = 0.2, .soft_max = 1, .unit = "", .label = "Smoothness",
       .doc = "Hurst exponent H: octave gain lacunarity^-H; 0 is rough, 1 smooth", .methods = kAll},
      {ROW(octaves, FT_PARAM_INT32), .since = kAbi218, .element_kind = -1, .default_value = 12, .hard_min = 1,
       .hard_max = noise::kMaxOctaves, .soft_min = 1, .soft_max = 24, .unit = "octaves", .label = "Octaves",
       .doc = "Noise octaves summed; 24 reach 2 m on the Earth (frequency x lacunarity^(octaves - 1) at most 2^30)",
       .methods = kFbm},
      {ROW(lacunarity, FT_PARAM_DOUBLE), .flags = kAbove, .since = kAbi218, .element_kind = -1, .default_value = 2,
       .hard_min = 1, .hard_max = kBig, .soft_min = 1.5, .soft_max = 4, .unit = "", .label = "Lacunarity",
       .doc = "Frequency ratio between octaves", .methods = kFbm},
      {ROW(frequency, FT_PARAM_DOUBLE), .flags = kAbove, .since = kAbi218, .element_kind = -1,
       .default_value = 1.5, .hard_min = 0, .hard_max = kBig, .soft_min = 0.5, .soft_max = 8, .unit = "",
       .label = "Continents",
       .doc = "About how many continents: the base octave's noise cells per radius (its frequency)",
       .methods = kFbm},
      {ROW(basis, FT_PARAM_ENUM), .since = kAbi218, .element_kind = -1, .default_value = noise::kBasisGradient,
       .hard_min = noise::kBasisValue, .hard_max = noise::kBasisCellularF2F1, .soft_min = noise::kBasisValue,
       .soft_max = noise::kBasisCellularF2F1, .unit = "", .label = "Noise Basis",
       .doc = "Noise basis of every octave, in 3D", .methods = kFbm, .enum_count = terrain_row("basis").enum_count,
       .enum_items = terrain_row("basis").enum_items},
      {ROW(variant, FT_PARAM_ENUM), .since = kAbi218, .element_kind = -1, .default_value = noise::kFbmStandard,
       .hard_min = noise::kFbmStandard, .hard_max = noise::kFbmHetero, .soft_min = noise::kFbmStandard,
       .soft_max = noise::kFbmHetero, .unit = "", .label = "Variant", .doc = terrain_row("variant").doc,
       .methods = kFbm, .enum_count = terrain_row("variant").enum_count,
       .enum_items = terrain_row("variant").enum_items},
      {ROW(offset, FT_PARAM_DOUBLE), .since = kAbi218, .element_kind = -1, .default_value = 1, .hard_min = -kBig,
       .hard_max = kBig, .soft_min = -2, .soft_max = 2, .unit = "", .label = "Offset",
       .doc = terrain_row("offset").doc, .methods = kFbm},
      {ROW(seed, FT_PARAM_UINT64), .since = kAbi218, .element_kind = -1, .default_value = 1, .hard_min = 0,
       .hard_max = 18446744073709551615.0, .soft_min = 0, .soft_max = 2147483647.0, .unit = "", .label = "Seed",
       .doc = "Random seed (Philox key): the same seed gives the same planet on every machine", .methods = kAll},
      {ROW(sea, FT_PARAM_ENUM), .since = kAbi218, .element_kind = -1, .default_value = FT_PLANET_SEA_NONE,
       .hard_min = FT_PLANET_SEA_NONE, .hard_max = FT_PLANET_SEA_FRACTION, .soft_min = FT_PLANET_SEA_NONE,
       .soft_max = FT_PLANET_SEA_FRACTION, .unit = "", .label = "Sea",
       .doc = "Raise the ground below a sea to it: at a height, or covering a share of the planet's area",
       .methods = kAll, .enum_count = 3, .enum_items = kSeas},
      {ROW(sea_level, FT_PARAM_DOUBLE), .since = kAbi218, .element_kind = -1, .default_value = 0, .hard_min = -1e30,
       .hard_max = 1e30, .soft_min = -5000, .soft_max = 5000, .unit = "metres", .label = "Sea Level",
       .doc = "Height of the sea above the radius (sea 'height')", .methods = kAll},
      {ROW(sea_fraction, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MAX_EXCLUSIVE, .since = kAbi218,
       .element_kind = -1, .default_value = 0.7, .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 0.95,
       .unit = "", .label = "Sea Fraction",
       .doc = "Share of the planet's area under the sea (sea 'fraction'; the Earth's is 0.71)", .methods = kAll},
      threads_row<ft_planet_params>(),
      progress_row<ft_planet_params>(),
      progress_user_row<ft_planet_params>(),
  };
  return kRows;
}
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& planet_param_table() {
  static const ParamTable table{"ft_planet_params", sizeof(ft_planet_params),
                                rows()};
  return table;
}

PlanetConfig from_c(const ft_planet_params& given) {
  const ft_planet_params p = upgraded(planet_param_table(), given);
  check_ranges(planet_param_table(), &p);
  PlanetConfig c;
  c.method = p.method;
  c.radius = p.radius;
  c.fbm.sigma = p.sigma;
  c.fbm.hurst = p.hurst;
  c.fbm.octaves = p.octaves;
  c.fbm.lacunarity = p.lacunarity;
  c.fbm.frequency = p.frequency;
  c.fbm.basis = p.basis;
  c.fbm.variant = p.variant;
  c.fbm.offset = p.offset;
  c.fbm.seed = p.seed;
  c.sea = p.sea;
  c.sea_level = p.sea_level;
  c.sea_fraction = p.sea_fraction;
  c.threads = p.threads;
  c.progress = Progress(p.progress, p.progress_user);
  return c;
}

}  // namespace ft::planet
