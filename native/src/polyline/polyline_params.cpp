// SPDX-License-Identifier: GPL-3.0-or-later
#include "polyline/polyline_params.hpp"

#include <cfloat>

#include "fracterra/polyline.h"
#include "polyline/classic_curves.hpp"
#include "polyline/fpl.hpp"

namespace ft::polyline {
namespace {

constexpr uint64_t kFpl = method_bit(FT_POLYLINE_FPL) | method_bit(FT_POLYLINE_FPL3D);
constexpr uint64_t kIfs = method_bit(FT_POLYLINE_IFS);
constexpr uint64_t kCurves = FT_PARAM_ALL_METHODS & ~kIfs;  // every method with a base polyline
constexpr uint64_t kProfile = method_bit(FT_POLYLINE_PROFILE);
constexpr double kInf = DBL_MAX;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;

constexpr ft_param_enum_item kMethods[] = {
    {FT_POLYLINE_FPL, "FPL", "FPL 2D",
     "Nikulin's fractal polyline (2018, seed 003): random orthogonal midpoint displacement in the x,y plane"},
    {FT_POLYLINE_FPL3D, "FPL3D", "FPL 3D", "The fractal polyline with 3D displacements (lightning)"},
    {FT_POLYLINE_KOCH, "KOCH", "Koch", "Koch curve (von Koch 1904) on every base segment, 4^depth segments each"},
    {FT_POLYLINE_DRAGON, "DRAGON", "Dragon", "Harter-Heighway dragon (Davis & Knuth 1970), 2^depth segments each"},
    {FT_POLYLINE_SIERPINSKI, "SIERPINSKI", "Sierpinski",
     "Sierpinski arrowhead curve (Sierpinski 1915; Mandelbrot 1982), 3^depth segments each"},
    {FT_POLYLINE_IFS, "IFS", "IFS Points",
     "Attractor of an iterated function system by random iteration (Barnsley 1988, seed 002), as points"},
    {FT_POLYLINE_PROFILE, "PROFILE", "Profile",
     "Voss 1D midpoint profile (Voss 1985, seed 000) laid across every base segment (a horizon)"},
};
constexpr ft_param_enum_item kRngs[] = {
    {FT_POLYLINE_RNG_UNIFORM, "UNIFORM", "Uniform", "urf(s): displacements uniform on [-s, s] (Nikulin 2018)"},
    {FT_POLYLINE_RNG_NORMAL, "NORMAL", "Normal", "nrf(sigma): displacements normal, standard deviation sigma"},
};
constexpr ft_param_enum_item kIfsPresets[] = {
    {FT_IFS_FERN, "FERN", "Fern", "Barnsley's fern (Barnsley 1988), 4 maps"},
    {FT_IFS_DRAGON, "DRAGON", "Dragon", "Harter-Heighway dragon, 2 maps"},
    {FT_IFS_KOCH, "KOCH", "Koch", "Koch curve, 4 maps"},
    {FT_IFS_SIERPINSKI_GASKET, "SIERPINSKI_GASKET", "Sierpinski Gasket",
     "Three maps of ratio 1/2 (Sierpinski 1915): dimension log 3 / log 2"},
};

#define ROW(field, type) FT_PARAM_ROW(ft_polyline_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_polyline_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_polyline_params), set by ft_polyline_params_init",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(method, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_POLYLINE_FPL, .hard_min = 0,
     .hard_max = FT_POLYLINE_PROFILE, .soft_min = 0, .soft_max = FT_POLYLINE_PROFILE, .unit = "", .label = "Method",
     .doc = "Which fractal curve", .methods = FT_PARAM_ALL_METHODS, .enum_count = 7, .enum_items = kMethods},
    {ROW(rng, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_POLYLINE_RNG_UNIFORM, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Generator",
     .doc = "Random generator rf of the displacements (Nikulin 2018)", .methods = kFpl, .enum_count = 2,
     .enum_items = kRngs},
    {ROW(depth, FT_PARAM_INT32), .element_kind = -1, .default_value = 8, .hard_min = 0, .hard_max = kMaxFplDepth,
     .soft_min = 0, .soft_max = 14, .unit = "levels", .label = "Detail Levels",
     .doc = "Recursion depth r: each base segment gets up to 2^r segments (Koch 4^r, at most 15; Sierpinski 3^r, "
            "at most 19; profile 1..28)",
     .methods = kCurves},
    {ROW(spread, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.1, .hard_min = 0, .hard_max = kInf,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Wildness",
     .doc = "Displacement s (uniform) or sigma (normal) per unit segment length (Nikulin 2018): below 0.1 "
            "lightning-like, 0.2-0.3 horizon-like, 0.3 and more Brownian loops; profile: its sigma (> 0)",
     .methods = kFpl | kProfile},
    {ROW(min_length, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = kInf,
     .soft_min = 0, .soft_max = 1, .unit = "scene units", .label = "Min Length",
     .doc = "delta: segments shorter than this are not split (Nikulin 2018)", .methods = kCurves},
    {ROW(seed, FT_PARAM_UINT64), .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 18446744073709551615.0, .soft_min = 0, .soft_max = 2147483647.0, .unit = "", .label = "Seed",
     .doc = "Random seed (Philox key): the same seed gives the same line on every machine",
     .methods = kFpl | kIfs | kProfile},
    {ROW(base, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_DOUBLE, .element_kind = -1,
     .unit = "scene units", .label = "Base Polyline",
     .doc = "Base polyline p1..pn as n xyz triples (not copied); NULL: the unit segment (0,0,0)-(1,0,0)",
     .methods = kCurves},
    {ROW(base_count, FT_PARAM_INT64), .flags = kData, .element_kind = -1, .hard_min = 0,
     .hard_max = 1073741824.0, .unit = "points", .label = "Base Points",
     .doc = "n >= 2 when base is given; consecutive nodes must differ", .methods = kCurves},
    {ROW(plane_normal, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = -kInf,
     .hard_max = kInf, .soft_min = -1, .soft_max = 1, .unit = "", .label = "Plane Normal",
     .doc = "FPL 3D: displacements lie in the plane with this normal; all zero: a random direction per midpoint",
     .methods = method_bit(FT_POLYLINE_FPL3D)},
    {ROW(branch_prob, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Branching",
     .doc = "Probability that a midpoint of recursion level l forks a side branch is branch_prob 2^(-l/2); "
            "0: a single line",
     .methods = kFpl},
    {ROW(branch_decay, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MIN_EXCLUSIVE | FT_PARAM_FLAG_MAX_EXCLUSIVE,
     .element_kind = -1, .default_value = 0.5, .hard_min = 0, .hard_max = 1, .soft_min = 0.05, .soft_max = 0.95,
     .unit = "", .label = "Branch Decay", .doc = "Length and radius factor per branch generation",
     .methods = kFpl},
    {ROW(branch_generations, FT_PARAM_INT32), .element_kind = -1, .default_value = 3, .hard_min = 1,
     .hard_max = 8, .soft_min = 1, .soft_max = 8, .unit = "", .label = "Branch Generations",
     .doc = "Deepest branch generation", .methods = kFpl},
    {ROW(ifs_preset, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_IFS_FERN, .hard_min = 0,
     .hard_max = FT_IFS_SIERPINSKI_GASKET, .soft_min = 0, .soft_max = FT_IFS_SIERPINSKI_GASKET, .unit = "",
     .label = "IFS", .doc = "Built-in iterated function system (seed 002), used when ifs_table is NULL",
     .methods = kIfs, .enum_count = 4, .enum_items = kIfsPresets},
    {ROW(radius, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.01, .hard_min = 0, .hard_max = kInf,
     .soft_min = 0, .soft_max = 1, .unit = "scene units", .label = "Radius",
     .doc = "Vertex radius at the start of the main line; with branches every line tapers to branch_decay "
            "times its start radius",
     .methods = kCurves},
    {ROW(hurst, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.8, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Smoothness",
     .doc = "Hurst exponent H of the profile (Voss 1985)", .methods = kProfile},
    {ROW(ifs_table, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_DOUBLE, .element_kind = -1,
     .unit = "", .label = "IFS Table",
     .doc = "NULL: ifs_preset; else ifs_maps rows (a, b, c, d, e, f, p): x' = a x + b y + e, y' = c x + d y + f, "
            "chosen with probability p",
     .methods = kIfs},
    {ROW(ifs_maps, FT_PARAM_INT32), .flags = kData, .element_kind = -1, .hard_min = 0, .hard_max = 64,
     .unit = "maps", .label = "IFS Maps", .doc = "Rows in ifs_table, 1..64", .methods = kIfs},
    threads_row<ft_polyline_params>(),
    {ROW(ifs_points, FT_PARAM_INT64), .element_kind = -1, .default_value = 100000, .hard_min = 1,
     .hard_max = 268435456.0, .soft_min = 1000, .soft_max = 1000000, .unit = "points", .label = "Points",
     .doc = "IFS attractor points to return", .methods = kIfs},
    progress_row<ft_polyline_params>(),
    progress_user_row<ft_polyline_params>(),
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& polyline_param_table() {
  static const ParamTable table{"ft_polyline_params", sizeof(ft_polyline_params), kRows};
  return table;
}

}  // namespace ft::polyline
