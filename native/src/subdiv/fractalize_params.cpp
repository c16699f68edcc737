// SPDX-License-Identifier: GPL-3.0-or-later
#include "subdiv/fractalize_params.hpp"

#include <cfloat>

#include "fracterra/subdiv.h"
#include "subdiv/fractalize.hpp"

namespace ft::subdiv {
namespace {

constexpr uint64_t kAll = FT_PARAM_ALL_METHODS;
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;

constexpr ft_param_enum_item kSchemes[] = {
    {FT_SCHEME_CATMARK, "CATMARK", "Catmull-Clark", "Catmull-Clark (1978): any polygons in, quads out"},
    {FT_SCHEME_LOOP, "LOOP", "Loop", "Loop (1987): triangles in (only), triangles out"},
    {FT_SCHEME_BILINEAR, "BILINEAR", "Bilinear", "Bilinear: any polygons in, quads out, no smoothing"},
};
constexpr ft_param_enum_item kModes[] = {
    {FT_FRACTALIZE_MIDPOINT, "MIDPOINT", "Midpoint",
     "Midpoint displacement (Voss 1985, seed 000): only the vertices new at level k move"},
    {FT_FRACTALIZE_ADDITIONS, "ADDITIONS", "Additions",
     "Successive random additions (Feder 1988, seed 001): every vertex moves"},
};

#define ROW(field, type) FT_PARAM_ROW(ft_fractalize_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_fractalize_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_fractalize_params), set by ft_fractalize_params_init", .methods = kAll},
    {ROW(levels, FT_PARAM_INT32), .element_kind = -1, .default_value = 4, .hard_min = 1,
     .hard_max = kMaxSubdivLevels, .soft_min = 1, .soft_max = 7, .unit = "levels", .label = "Detail Levels",
     .doc = "Refinement steps L of the subdivision (faces grow 4^L)", .methods = kAll},
    {ROW(hurst, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.8, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Smoothness",
     .doc = "Hurst exponent H (Voss 1985): level k moves by sigma 2^(-kH) g", .methods = kAll},
    {ROW(sigma, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.1, .hard_min = 0, .hard_max = DBL_MAX,
     .soft_min = 0, .soft_max = 1, .unit = "scene units", .label = "Roughness",
     .doc = "Displacement scale sigma in mesh units (with scale_by_edge_length: a fraction of the local base edge "
            "length); 0: plain subdivision",
     .methods = kAll},
    {ROW(seed, FT_PARAM_UINT64), .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 18446744073709551615.0, .soft_min = 0, .soft_max = 2147483647.0, .unit = "", .label = "Seed",
     .doc = "Random seed (Philox key, with level and vertex index)", .methods = kAll},
    {ROW(scheme, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_SCHEME_CATMARK, .hard_min = 0,
     .hard_max = FT_SCHEME_BILINEAR, .soft_min = 0, .soft_max = FT_SCHEME_BILINEAR, .unit = "", .label = "Scheme",
     .doc = "Subdivision scheme (OpenSubdiv)", .methods = kAll, .enum_count = 3, .enum_items = kSchemes},
    {ROW(mode, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_FRACTALIZE_MIDPOINT, .hard_min = 0,
     .hard_max = FT_FRACTALIZE_ADDITIONS, .soft_min = 0, .soft_max = FT_FRACTALIZE_ADDITIONS, .unit = "",
     .label = "Displacement", .doc = "Which vertices move at each level", .methods = kAll, .enum_count = 2,
     .enum_items = kModes},
    {ROW(fix_boundary, FT_PARAM_BOOL), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Fix Boundary",
     .doc = "Vertices on a boundary (open edge) never move", .methods = kAll},
    {ROW(scale_by_edge_length, FT_PARAM_BOOL), .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Scale by Edge Length",
     .doc = "Multiply by the base mesh's mean edge length at each vertex, interpolated over the surface",
     .methods = kAll},
    {ROW(weights, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_FLOAT, .element_kind = -1,
     .unit = "", .label = "Weights",
     .doc = "NULL, or one weight per base vertex (a painted mask, finite), interpolated like positions",
     .methods = kAll},
    threads_row<ft_fractalize_params>(),
    progress_row<ft_fractalize_params>("Called once per level; may cancel; NULL: none"),
    progress_user_row<ft_fractalize_params>(),
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& fractalize_param_table() {
  static const ParamTable table{"ft_fractalize_params", sizeof(ft_fractalize_params), kRows};
  return table;
}

ft_fractalize_params default_fractalize_params() {
  return defaults_of<ft_fractalize_params>(fractalize_param_table());
}

}  // namespace ft::subdiv
