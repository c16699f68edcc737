// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/terrain_params.hpp"

#include <array>
#include <cfloat>
#include <cmath>

#include "fracterra/terrain.h"
#include "noise/fbm.hpp"
#include "terrain/interpolated.hpp"
#include "terrain/landform.hpp"
#include "terrain/mandelbrot.hpp"
#include "terrain/terrain.hpp"
#include "terrain/terrain_methods.hpp"

namespace ft::terrain {
namespace {

// The masks of capabilities come from the method table (terrain_methods.hpp);
// those of one method's own fields name it.
constexpr uint64_t kDyadic = method_mask([](const TerrainMethod& m) { return m.dyadic; });
constexpr uint64_t kFree = method_mask([](const TerrainMethod& m) { return !m.dyadic; });
constexpr uint64_t kRandom = method_mask([](const TerrainMethod& m) { return m.seeded; });
constexpr uint64_t kReference = method_mask([](const TerrainMethod& m) { return m.reference; });
// The Tileable setting: spectral synthesis always tiles and the Mandelbrot set never does.
constexpr uint64_t kCanTile = method_mask([](const TerrainMethod& m) { return m.tiling == Tiling::kOnRequest; });
constexpr uint64_t kFbm = method_bit(FT_TERRAIN_FBM);
constexpr uint64_t kMandelbrot = method_bit(FT_TERRAIN_MANDELBROT);
constexpr uint32_t kAbi11 = 0x10001, kAbi12 = 0x10002, kAbi26 = 0x20006, kAbi29 = 0x20009;

// The method enum's items are the table's rows' items.
constexpr auto kMethods = [] {
  std::array<ft_param_enum_item, kTerrainMethodCount> items{};
  for (int32_t i = 0; i < kTerrainMethodCount; ++i) items[size_t(i)] = kTerrainMethods[i].item;
  return items;
}();
constexpr ft_param_enum_item kReferenceScales[] = {
    {FT_REFSCALE_SIGMA, "SIGMA", "Sigma", "Displace the refinement by sigma as given"},
    {FT_REFSCALE_MEAN, "MEAN", "Mean", "Scale the refinement by the mean of |reference values| (Voss 1985, "
                                       "seed 000, fig. 7b)"},
    {FT_REFSCALE_STD, "STD", "Std Dev", "Scale the refinement by the standard deviation of the reference values"},
};
constexpr ft_param_enum_item kBases[] = {
    {FT_BASIS_VALUE, "VALUE", "Value", "Lattice value noise, quintic interpolation"},
    {FT_BASIS_GRADIENT, "GRADIENT", "Gradient", "Perlin gradient noise (Perlin 2002)"},
    {FT_BASIS_SIMPLEX, "SIMPLEX", "Simplex", "Simplex noise (Perlin 2001); not periodic"},
    {FT_BASIS_CELLULAR_F1, "CELLULAR_F1", "Cellular F1", "Voronoi distance to the nearest feature point "
                                                         "(Worley 1996)"},
    {FT_BASIS_CELLULAR_F2F1, "CELLULAR_F2F1", "Cellular F2-F1", "Voronoi F2 - F1: ridges between cells "
                                                               "(Worley 1996)"},
};
constexpr ft_param_enum_item kVariants[] = {
    {FT_FBM_STANDARD, "STANDARD", "Standard", "Plain fBm: the sum of octaves"},
    {FT_FBM_RIDGED, "RIDGED", "Ridged", "Ridged multifractal (Musgrave 1994): sharp crests"},
    {FT_FBM_HYBRID, "HYBRID", "Hybrid", "Musgrave's hybrid multifractal (1994): smooth valleys, rough peaks"},
    {FT_FBM_HETERO, "HETERO", "Hetero", "Musgrave's heterogeneous terrain (1994)"},
};

constexpr ft_param_enum_item kFalloffs[] = {
    {FT_FALLOFF_NONE, "NONE", "None", "Heights run to the edges as generated"},
    {FT_FALLOFF_SQUARE, "SQUARE", "Square", "Heights fall to the edge level along all four edges"},
    {FT_FALLOFF_RADIAL, "RADIAL", "Radial", "Heights fall to the edge level towards the inscribed ellipse: an "
                                            "island"},
    {FT_FALLOFF_CUSTOM, "CUSTOM", "Custom", "A mask spanning the terrain (an image; in Blender also an "
                                            "object's outline): white keeps the height, black gives the edge "
                                            "level, grey between"},
};
constexpr ft_param_enum_item kSeas[] = {
    {FT_SEA_NONE, "NONE", "None", "No sea"},
    {FT_SEA_HEIGHT, "HEIGHT", "Height", "A sea at a height in scene units; lower ground becomes flat sea"},
    {FT_SEA_FRACTION, "FRACTION", "Fraction", "A sea covering a fraction of the terrain, whatever the seed: the "
                                              "height with that fraction of the samples below it (whole terrains "
                                              "only, not windows)"},
};

constexpr double kInf = DBL_MAX;  // "any finite value" as a bound
constexpr uint32_t kData = FT_PARAM_FLAG_DATA;
constexpr uint32_t kAbove = FT_PARAM_FLAG_MIN_EXCLUSIVE;
#define ROW(field, type) FT_PARAM_ROW(ft_terrain_params, field, type)

FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kTerrainRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_terrain_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_terrain_params), set by ft_terrain_params_init",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(method, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_TERRAIN_MIDPOINT,
     .hard_min = 0, .hard_max = kTerrainMethodCount - 1, .soft_min = 0, .soft_max = kTerrainMethodCount - 1,
     .unit = "", .label = "Method", .doc = "How the terrain is synthesised", .methods = FT_PARAM_ALL_METHODS,
     .enum_count = kTerrainMethodCount, .enum_items = kMethods.data()},
    {ROW(levels, FT_PARAM_INT32), .element_kind = -1, .default_value = 9, .hard_min = 1, .hard_max = kMaxLevels,
     .soft_min = 1, .soft_max = 12, .unit = "levels", .label = "Detail Levels",
     .doc = "Refinement steps n (Voss 1985): the grid has 2^n + 1 samples per side (9: 513, 10: 1025)",
     .methods = kDyadic},
    {ROW(width, FT_PARAM_INT32), .element_kind = -1, .default_value = 513, .hard_min = 2, .hard_max = 65536,
     .soft_min = 2, .soft_max = 4097, .unit = "samples", .label = "Samples X",
     .doc = "Samples along x (the methods other than midpoint and additions)", .methods = kFree},
    {ROW(height, FT_PARAM_INT32), .element_kind = -1, .default_value = 513, .hard_min = 2, .hard_max = 65536,
     .soft_min = 2, .soft_max = 4097, .unit = "samples", .label = "Samples Y",
     .doc = "Samples along y (the methods other than midpoint and additions)", .methods = kFree},
    // Soft minimum 0.2: a drag below it gives spikes (H 0 at sigma 1: +-6.5 m on a 10 m terrain).
    {ROW(hurst, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.8, .hard_min = 0, .hard_max = 1,
     .soft_min = 0.2, .soft_max = 1, .unit = "", .label = "Smoothness",
     .doc = "Hurst exponent H (Mandelbrot & Van Ness 1968; Voss 1985): 0 is rough (fractal dimension 3), "
            "1 smooth (dimension 2)",
     .methods = kRandom},
    {ROW(sigma, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = kInf, .soft_min = 0.01, .soft_max = 100, .unit = "scene units", .label = "Height Scale",
     .doc = "Vertical scale sigma: the standard deviation of the first displacement (Voss 1985)",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(seed, FT_PARAM_UINT64), .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 18446744073709551615.0, .soft_min = 0, .soft_max = 2147483647.0, .unit = "",
     .label = "Seed", .doc = "Random seed (Philox key): the same seed gives the same terrain on every machine",
     .methods = kRandom},
    {ROW(periodic, FT_PARAM_BOOL), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Tileable",
     .doc = "Periodic: wrap-around neighbours, the terrain tiles seamlessly (fbm: whole cells per period, no "
            "octave rotation, not simplex); spectral synthesis always tiles",
     .methods = kCanTile},
    threads_row<ft_terrain_params>(),
    {ROW(reference, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_FLOAT, .element_kind = -1,
     .unit = "scene units", .label = "Reference Points",
     .doc = "Reference heights (Voss 1985, seed 000): a coarse (2^m + 1)^2 grid, row-major, taken as steps "
            "1..m; NULL: none",
     .methods = kReference},
    {ROW(reference_size, FT_PARAM_INT32), .flags = kData, .element_kind = -1, .default_value = 0,
     .hard_min = 0, .hard_max = 65537, .unit = "samples", .label = "Reference Size",
     .doc = "Side of the reference grid, 2^m + 1 with 1 <= m <= levels", .methods = kReference},
    {ROW(reference_scale, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_REFSCALE_SIGMA,
     .hard_min = FT_REFSCALE_SIGMA, .hard_max = FT_REFSCALE_STD, .soft_min = FT_REFSCALE_SIGMA,
     .soft_max = FT_REFSCALE_STD, .unit = "", .label = "Refinement Scale",
     .doc = "Displacement scale of the steps after the reference grid (Voss 1985, seed 000, fig. 7 a, b)",
     .methods = kReference, .enum_count = 3, .enum_items = kReferenceScales},
    {ROW(octaves, FT_PARAM_INT32), .element_kind = -1, .default_value = 8, .hard_min = 1,
     .hard_max = noise::kMaxOctaves, .soft_min = 1, .soft_max = 16, .unit = "octaves", .label = "Octaves",
     .doc = "Noise octaves summed (Quilez 2019, seed 004); the finest must stay within float resolution",
     .methods = kFbm},
    {ROW(lacunarity, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 2, .hard_min = 1,
     .hard_max = kInf, .soft_min = 1.5, .soft_max = 4, .unit = "", .label = "Lacunarity",
     .doc = "Frequency ratio between octaves (fbm; Quilez 2019), or the scale factor 1/r per cycle of the "
            "interpolated method (at most 16; Feder 1988)",
     .methods = kFbm | method_bit(FT_TERRAIN_INTERPOLATED)},
    {ROW(gain, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = -kInf, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Gain",
     .doc = "Amplitude ratio G between octaves (Quilez 2019); <= 0: lacunarity^-H, i.e. 2^-H at lacunarity 2",
     .methods = kFbm},
    {ROW(basis, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_BASIS_GRADIENT,
     .hard_min = FT_BASIS_VALUE, .hard_max = FT_BASIS_CELLULAR_F2F1, .soft_min = FT_BASIS_VALUE,
     .soft_max = FT_BASIS_CELLULAR_F2F1, .unit = "", .label = "Noise",
     .doc = "Noise basis of every octave", .methods = kFbm, .enum_count = 5, .enum_items = kBases},
    {ROW(variant, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_FBM_STANDARD,
     .hard_min = FT_FBM_STANDARD, .hard_max = FT_FBM_HETERO, .soft_min = FT_FBM_STANDARD,
     .soft_max = FT_FBM_HETERO, .unit = "", .label = "Variant", .doc = "How the octaves combine",
     .methods = kFbm, .enum_count = 4, .enum_items = kVariants},
    {ROW(frequency, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 4, .hard_min = 0,
     .hard_max = kInf, .soft_min = 0.5, .soft_max = 64, .unit = "cells", .label = "Feature Count",
     .doc = "Base-octave frequency: lattice cells across the width", .methods = kFbm},
    {ROW(offset, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 1, .hard_min = -kInf, .hard_max = kInf,
     .soft_min = -2, .soft_max = 2, .unit = "", .label = "Offset",
     .doc = "Offset of the ridged, hybrid and hetero variants (Musgrave 1994)", .methods = kFbm},
    {ROW(octave_rotation, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.5, .hard_min = -kInf,
     .hard_max = kInf, .soft_min = -M_PI, .soft_max = M_PI, .unit = "radians", .label = "Octave Rotation",
     .doc = "Domain rotation per octave (Quilez 2019): hides the alignment of the octaves' zeros and peaks; "
            "not with periodic",
     .methods = kFbm},
    {ROW(warp, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0, .hard_min = 0, .hard_max = noise::kMaxWarp,
     .soft_min = 0, .soft_max = 4, .unit = "cells", .label = "Warp",
     .doc = "Domain-warp displacement in base cells (Quilez 2002), 0: off", .methods = kFbm},
    progress_row<ft_terrain_params>(),
    progress_user_row<ft_terrain_params>(),
    {ROW(world_size, FT_PARAM_DOUBLE), .flags = kAbove, .since = kAbi11, .element_kind = -1, .default_value = 10,
     .hard_min = 0, .hard_max = kInf, .soft_min = 1, .soft_max = 10000, .unit = "scene units",
     .label = "World Size",
     .doc = "Extent of the terrain along x; y follows the aspect ratio; heights are in the same units",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(center_x, FT_PARAM_DOUBLE), .since = kAbi12, .element_kind = -1, .default_value = -0.5,
     .hard_min = -kMandelbrotCenterLimit, .hard_max = kMandelbrotCenterLimit, .soft_min = -2, .soft_max = 1,
     .unit = "", .label = "Center X", .doc = "Real part of the view's centre in the complex plane (seed 002)",
     .methods = kMandelbrot},
    {ROW(center_y, FT_PARAM_DOUBLE), .since = kAbi12, .element_kind = -1, .default_value = 0,
     .hard_min = -kMandelbrotCenterLimit, .hard_max = kMandelbrotCenterLimit, .soft_min = -1.5, .soft_max = 1.5,
     .unit = "", .label = "Center Y", .doc = "Imaginary part of the view's centre (row 0 is the top)",
     .methods = kMandelbrot},
    {ROW(zoom, FT_PARAM_DOUBLE), .since = kAbi12, .element_kind = -1, .default_value = 1,
     .hard_min = kMandelbrotMinZoom, .hard_max = kInf, .soft_min = 0.5, .soft_max = 1e6, .unit = "",
     .label = "Zoom",
     .doc = "The width spans 4 / zoom of the complex plane; refused beyond double precision (neighbouring "
            "samples >= 64 ulp apart: about 1e11 at 1025 samples across)",
     .methods = kMandelbrot},
    {ROW(iterations, FT_PARAM_INT32), .since = kAbi12, .element_kind = -1, .default_value = 64, .hard_min = 1,
     .hard_max = kMaxMandelbrotIterations, .soft_min = 8, .soft_max = 4096, .unit = "iterations",
     .label = "Iterations",
     .doc = "Maximum iterations of z <- z^2 + c: points that have not escaped are the set, a plateau; fewer "
            "make a lower wall where the slopes meet it",
     .methods = kMandelbrot},
    {ROW(supersample, FT_PARAM_INT32), .since = kAbi12, .element_kind = -1, .default_value = 2, .hard_min = 1,
     .hard_max = kMaxMandelbrotSupersample, .soft_min = 1, .soft_max = 4, .unit = "", .label = "Supersample",
     .doc = "k x k points of the plane averaged per sample (anti-aliasing the boundary; k^2 times the work)",
     .methods = kMandelbrot},
    {ROW(levelling, FT_PARAM_DOUBLE), .since = kAbi26, .element_kind = -1, .default_value = 0, .hard_min = 0,
     .hard_max = 1, .soft_min = 0, .soft_max = 1, .unit = "", .label = "Remove Tilt",
     .doc = "Levelling: how much of the tilt to remove, the bilinear surface through the whole terrain's four "
            "corners (1: every corner at height 0, a level terrain)",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(height_offset, FT_PARAM_DOUBLE), .since = kAbi26, .element_kind = -1, .default_value = 0,
     .hard_min = -kMaxLandformHeight, .hard_max = kMaxLandformHeight, .soft_min = -100, .soft_max = 100,
     .unit = "scene units", .label = "Height Offset", .doc = "Added to every height (after the levelling)",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(falloff, FT_PARAM_ENUM), .since = kAbi26, .element_kind = -1, .default_value = FT_FALLOFF_NONE,
     .hard_min = FT_FALLOFF_NONE, .hard_max = FT_FALLOFF_CUSTOM, .soft_min = FT_FALLOFF_NONE,
     .soft_max = FT_FALLOFF_CUSTOM, .unit = "", .label = "Falloff",
     .doc = "Heights fall smoothly to the edge level near the edges (square), towards an inscribed ellipse "
            "(radial: an island) or where a mask is dark (custom), so the terrain does not end in a wall",
     .methods = FT_PARAM_ALL_METHODS, .enum_count = 4, .enum_items = kFalloffs},
    {ROW(falloff_width, FT_PARAM_DOUBLE), .flags = kAbove, .since = kAbi26, .element_kind = -1,
     .default_value = 0.3, .hard_min = 0, .hard_max = 1, .soft_min = 0.05, .soft_max = 1, .unit = "",
     .label = "Falloff Width",
     .doc = "Width of the band where heights fall, as a fraction of the half width (1: all the way from the "
            "centre); a smoothstep across it",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(edge_level, FT_PARAM_DOUBLE), .since = kAbi26, .element_kind = -1, .default_value = 0,
     .hard_min = -kMaxLandformHeight, .hard_max = kMaxLandformHeight, .soft_min = -100, .soft_max = 100,
     .unit = "scene units", .label = "Edge Level", .doc = "The height the edge falloff reaches at the edge",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(sea, FT_PARAM_ENUM), .since = kAbi26, .element_kind = -1, .default_value = FT_SEA_NONE,
     .hard_min = FT_SEA_NONE, .hard_max = FT_SEA_FRACTION, .soft_min = FT_SEA_NONE, .soft_max = FT_SEA_FRACTION,
     .unit = "", .label = "Sea",
     .doc = "Flatten the ground below a sea: at a height, or covering a fraction of the terrain (the same share "
            "of sea for every seed)",
     .methods = FT_PARAM_ALL_METHODS, .enum_count = 3, .enum_items = kSeas},
    {ROW(sea_level, FT_PARAM_DOUBLE), .since = kAbi26, .element_kind = -1, .default_value = 0,
     .hard_min = -kMaxLandformHeight, .hard_max = kMaxLandformHeight, .soft_min = -100, .soft_max = 100,
     .unit = "scene units", .label = "Sea Level", .doc = "Height of the sea (sea 'height')",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(sea_fraction, FT_PARAM_DOUBLE), .flags = FT_PARAM_FLAG_MAX_EXCLUSIVE, .since = kAbi26,
     .element_kind = -1, .default_value = 0.3, .hard_min = 0, .hard_max = 1, .soft_min = 0, .soft_max = 0.95,
     .unit = "", .label = "Sea Fraction",
     .doc = "Share of the terrain under the sea (sea 'fraction'): the sea is at that quantile of the heights",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(falloff_mask, FT_PARAM_POINTER), .flags = kData, .since = kAbi29, .element_type = FT_PARAM_FLOAT,
     .element_kind = -1, .unit = "", .label = "Falloff Mask",
     .doc = "The custom falloff's mask: width x height values in [0, 1], row-major, spanning the whole terrain "
            "corner to corner, resampled bilinearly (1 keeps the height, 0 gives the edge level); NULL: none",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(falloff_mask_width, FT_PARAM_INT32), .flags = kData, .since = kAbi29, .element_kind = -1,
     .default_value = 0, .hard_min = 0, .hard_max = kMaxMaskSide, .unit = "samples", .label = "Falloff Mask Width",
     .doc = "Columns of the falloff mask, 2..65536 with the custom falloff", .methods = FT_PARAM_ALL_METHODS},
    {ROW(falloff_mask_height, FT_PARAM_INT32), .flags = kData, .since = kAbi29, .element_kind = -1,
     .default_value = 0, .hard_min = 0, .hard_max = kMaxMaskSide, .unit = "samples",
     .label = "Falloff Mask Height", .doc = "Rows of the falloff mask, 2..65536 with the custom falloff",
     .methods = FT_PARAM_ALL_METHODS},
};
FT_PARAM_TABLE_END
#undef ROW

#define ROW(field, type) FT_PARAM_ROW(ft_profile_params, field, type)
FT_PARAM_TABLE_BEGIN
constexpr ft_param_info kProfileRows[] = {
    {ROW(struct_size, FT_PARAM_UINT32), .flags = FT_PARAM_FLAG_STRUCT_SIZE, .element_kind = -1,
     .default_value = sizeof(ft_profile_params), .hard_min = 0, .hard_max = 4294967295.0, .unit = "bytes",
     .label = "Struct Size", .doc = "sizeof(ft_profile_params), set by ft_profile_params_init",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(levels, FT_PARAM_INT32), .element_kind = -1, .default_value = 10, .hard_min = 1,
     .hard_max = kMaxProfileLevels, .soft_min = 1, .soft_max = 20, .unit = "levels", .label = "Detail Levels",
     .doc = "Refinement steps n of Voss's 1D midpoint displacement (1985, seed 000): 2^n + 1 samples",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(hurst, FT_PARAM_DOUBLE), .element_kind = -1, .default_value = 0.8, .hard_min = 0, .hard_max = 1,
     .soft_min = 0, .soft_max = 1, .unit = "", .label = "Smoothness",
     .doc = "Hurst exponent H (Mandelbrot & Van Ness 1968; Voss 1985): 0 rough, 1 smooth",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(sigma, FT_PARAM_DOUBLE), .flags = kAbove, .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = kInf, .soft_min = 0.01, .soft_max = 100, .unit = "scene units", .label = "Height Scale",
     .doc = "Vertical scale sigma: the standard deviation of the first displacement (Voss 1985)",
     .methods = FT_PARAM_ALL_METHODS},
    {ROW(seed, FT_PARAM_UINT64), .element_kind = -1, .default_value = 1, .hard_min = 0,
     .hard_max = 18446744073709551615.0, .soft_min = 0, .soft_max = 2147483647.0, .unit = "", .label = "Seed",
     .doc = "Random seed (Philox key)", .methods = FT_PARAM_ALL_METHODS},
    {ROW(reference, FT_PARAM_POINTER), .flags = kData, .element_type = FT_PARAM_FLOAT, .element_kind = -1,
     .unit = "scene units", .label = "Reference Points",
     .doc = "NULL or 2^m + 1 values taken as steps 1..m (Voss 1985, seed 000)", .methods = FT_PARAM_ALL_METHODS},
    {ROW(reference_size, FT_PARAM_INT32), .flags = kData, .element_kind = -1, .hard_min = 0,
     .hard_max = 268435457.0, .unit = "samples", .label = "Reference Size",
     .doc = "2^m + 1 with 1 <= m <= levels", .methods = FT_PARAM_ALL_METHODS},
    {ROW(reference_scale, FT_PARAM_ENUM), .element_kind = -1, .default_value = FT_REFSCALE_SIGMA,
     .hard_min = FT_REFSCALE_SIGMA, .hard_max = FT_REFSCALE_STD, .soft_min = FT_REFSCALE_SIGMA,
     .soft_max = FT_REFSCALE_STD, .unit = "", .label = "Refinement Scale",
     .doc = "Displacement scale of the steps after the reference values (Voss 1985, seed 000, fig. 7 a, b)",
     .methods = FT_PARAM_ALL_METHODS, .enum_count = 3, .enum_items = kReferenceScales},
    progress_row<ft_profile_params>(),
    progress_user_row<ft_profile_params>(),
};
FT_PARAM_TABLE_END
#undef ROW

}  // namespace

const ParamTable& profile_param_table() {
  static const ParamTable table{"ft_profile_params", sizeof(ft_profile_params), kProfileRows};
  return table;
}

const ParamTable& terrain_param_table() {
  static const ParamTable table{"ft_terrain_params", sizeof(ft_terrain_params), kTerrainRows};
  return table;
}

}  // namespace ft::terrain
