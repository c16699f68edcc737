// SPDX-License-Identifier: GPL-3.0-or-later
#include "refine/dem_refine_params.hpp"

#include <cfloat>
#include <cstdint>

namespace ft::refine {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;
constexpr double kInf = DBL_MAX;

constexpr ft_param_enum_item kMethods[] = {
    {kRefineMidpoint, "MIDPOINT", "Midpoint",
     "Voss midpoint displacement (Voss 1985, seed 000): the DEM's samples stay, new nodes between them"},
    {kRefineAdditions, "ADDITIONS", "Additions",
     "Successive random additions (Feder 1988, seed 001): every node moves at every level, the DEM's too"},
};

#define ROW(field, type) FT_PARAM_ROW(ft_dem_refine_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_dem_refine_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_dem_refine_params), set by ft_dem_refine_params_init",
     .methods = kAll},
    {ROW(levels_added, FT_PARAM_INT32), .element_kind = -1, .default_value = 2, .hard_min = 1,
     .hard_max = kMaxRefineLevels, .soft_min = 1, .soft_max = 4, .unit = "levels", .label = "Added Levels",
     .doc = "K: the window's side grows 2^K times", .methods = kAll},
    {ROW(hurst, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = -1, .hard_min = -kInf, .hard_max = 0.99,
     .soft_min = 0, .soft_max = 0.99, .unit = "", .label = "Smoothness",
     .doc = "Hurst exponent H in [0, 0.99] of the added levels; < 0: measured on the DEM (aligned variogram)",
     .methods = kAll},
    {ROW(sigma, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = -1, .hard_min = -kInf, .hard_max = kInf,
     .soft_min = 0, .soft_max = 100, .unit = "height units", .label = "Roughness",
     .doc = "Vertical scale sigma > 0 of the added levels; <= 0: from the DEM's increments at one pixel",
     .methods = kAll},
    {ROW(seed, FT_PARAM_UINT64), .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 18446744073709551615.0, .soft_min = 0, .soft_max = 2147483647.0, .unit = "", .label = "Seed",
     .doc = "Random seed of the added detail", .methods = kAll},
    {ROW(method, FT_PARAM_ENUM), .element_kind = -1, .default_value = kRefineMidpoint, .hard_min = 0,
     .hard_max = kRefineAdditions, .soft_min = 0, .soft_max = kRefineAdditions, .unit = "", .label = "Method",
     .doc = "How the levels are added (FT_TERRAIN_MIDPOINT or FT_TERRAIN_ADDITIONS)", .methods = kAll,
     .enum_count = 2, .enum_items = kMethods},
    {ROW(window_x, FT_PARAM_INT32), .element_kind = -1, .default_value = -1, .hard_min = -1, .hard_max = INT32_MAX,
     .soft_min = -1, .soft_max = 4096, .unit = "samples", .label = "Window X",
     .doc = "Column of the window's top-left sample; -1 (with window_y -1): the valid window nearest the centre",
     .methods = kAll},
    {ROW(window_y, FT_PARAM_INT32), .element_kind = -1, .default_value = -1, .hard_min = -1, .hard_max = INT32_MAX,
     .soft_min = -1, .soft_max = 4096, .unit = "samples", .label = "Window Y",
     .doc = "Row of the window's top-left sample; -1: the valid window nearest the centre", .methods = kAll},
    {ROW(window_side, FT_PARAM_INT32), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = INT32_MAX,
     .soft_min = 0, .soft_max = 4097, .unit = "samples", .label = "Window Side",
     .doc = "The window's side 2^m + 1; 0: the largest without nodata", .methods = kAll},
    threads_row<ft_dem_refine_params>(),
    progress_row<ft_dem_refine_params>("Called as the work advances; may cancel; NULL: none"),
    progress_user_row<ft_dem_refine_params>(),
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& dem_refine_param_table() {
  static const ParamTable table{"ft_dem_refine_params", sizeof(ft_dem_refine_params), kRows};
  return table;
}

DemRefineConfig dem_refine_config(const ft_dem_refine_params& p) {
  check_ranges(dem_refine_param_table(), &p);  // the window against the DEM is refine_dem's to check
  DemRefineConfig c;
  c.levels_added = p.levels_added;
  c.hurst = p.hurst;
  c.sigma = p.sigma;
  c.seed = p.seed;
  c.additions = p.method == kRefineAdditions;
  c.window_x = p.window_x;
  c.window_y = p.window_y;
  c.window_side = p.window_side;
  c.threads = p.threads;
  c.progress = p.progress;
  c.progress_user = p.progress_user;
  return c;
}

}  // namespace ft::refine
