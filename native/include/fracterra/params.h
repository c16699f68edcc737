// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/params.h
/// The library describes its own parameter structs: for every field of every
/// params struct its name, type, offset, default, hard and soft range, unit,
/// enum names and labels, a plain label, documentation, and the methods that
/// use it. The CLI builds its flags from this, the ctypes binding its
/// Structures, the Blender add-on its properties, and the library its range
/// checks and its upgrading of structs from older callers: a parameter is
/// defined once, in its struct and its row.
///
/// All strings and rows are static storage, valid for the life of the library.
#ifndef FRACTERRA_PARAMS_H
#define FRACTERRA_PARAMS_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// The described structs (the `kind` argument below).
enum {
  FT_PARAMS_TERRAIN = 0,         ///< ft_terrain_params (terrain.h)
  FT_PARAMS_PROFILE = 1,         ///< ft_profile_params (terrain.h)
  FT_PARAMS_POLYLINE = 2,        ///< ft_polyline_params (polyline.h)
  FT_PARAMS_FRACTALIZE = 3,      ///< ft_fractalize_params (subdiv.h)
  FT_PARAMS_POV_SCENE = 4,       ///< ft_pov_scene_params (povray.h; ABI 2.5)
  FT_PARAMS_POV_SWEEP = 5,       ///< ft_pov_sweep_params (povray.h; ABI 2.5)
  FT_PARAMS_HURST = 6,           ///< ft_hurst_params (analysis.h; ABI 2.5)
  FT_PARAMS_CLOUDS = 7,          ///< ft_clouds_params (analysis.h; ABI 2.5)
  FT_PARAMS_DEM_REFINE = 8,      ///< ft_dem_refine_params (raster.h; ABI 2.5)
  FT_PARAMS_EROSION = 9,         ///< ft_erosion_params (erosion.h; ABI 2.8)
  FT_PARAMS_BUILD = 10,          ///< ft_build_params (pipeline.h; ABI 2.13)
  FT_PARAMS_HYDROLOGY = 11,      ///< ft_hydrology_params (hydrology.h; ABI 2.15)
  FT_PARAMS_PLANET = 12,         ///< ft_planet_params (planet.h; ABI 2.18)
  FT_PARAMS_SPLAT = 13,          ///< ft_splat_params, one splat layer's rule (splat.h; ABI 2.19)
  FT_PARAMS_KIND_COUNT = 14      ///< number of kinds; kinds are 0 .. count - 1
};

/// Field types. Integers and doubles are the C types of the same name;
/// BOOL and ENUM are int32_t (BOOL: 0 or non-zero; ENUM: one of the row's
/// items); POINTER is a data pointer (its element type is `element_type`),
/// STRING a NUL-terminated `const char*`, CALLBACK an ft_progress_fn.
enum {
  FT_PARAM_UINT32 = 0,
  FT_PARAM_INT32 = 1,
  FT_PARAM_INT64 = 2,
  FT_PARAM_UINT64 = 3,
  FT_PARAM_FLOAT = 4,
  FT_PARAM_DOUBLE = 5,
  FT_PARAM_BOOL = 6,
  FT_PARAM_ENUM = 7,
  FT_PARAM_POINTER = 8,
  FT_PARAM_STRING = 9,
  FT_PARAM_CALLBACK = 10,
  FT_PARAM_OPAQUE = 11           ///< only as an element type: a handle (ft_heightfield, ...)
};

/// Row flags.
enum {
  FT_PARAM_FLAG_STRUCT_SIZE = 1, ///< the leading struct_size field
  FT_PARAM_FLAG_DATA = 2,        ///< data handed over by the program (pointers, their counts,
                                 ///< callbacks), not a setting: no CLI flag, no UI property
  FT_PARAM_FLAG_MIN_EXCLUSIVE = 4, ///< the value must be > hard_min (not >=)
  FT_PARAM_FLAG_MAX_EXCLUSIVE = 8, ///< the value must be < hard_max (not <=)
  FT_PARAM_FLAG_ZERO_IS_AUTO = 16  ///< 0 is accepted too, outside the hard range: "auto", the
                                   ///< library picks the value (the row's doc says how); ABI 2.11
};

/// Every method of the struct (its `method` field) uses the field.
#define FT_PARAM_ALL_METHODS (~(uint64_t)0)

/// One value of an FT_PARAM_ENUM field.
typedef struct ft_param_enum_item {
  int32_t value;                 ///< the C value (FT_TERRAIN_MIDPOINT, ...)
  const char* name;              ///< identifier: upper case, e.g. "MIDPOINT" (CLI: lower case)
  const char* label;             ///< plain words for a menu, e.g. "Midpoint"
  const char* doc;               ///< one sentence: what it is, with its source
} ft_param_enum_item;

/// One field of a params struct.
typedef struct ft_param_info {
  uint32_t struct_size;          ///< sizeof(ft_param_info) of the library (rows may grow at the end)
  int32_t type;                  ///< FT_PARAM_*
  const char* name;              ///< the C field name, also the CLI flag (underscores as dashes),
                                 ///< the Python attribute and the Blender property
  uint32_t offset;               ///< offsetof in the struct
  uint32_t size;                 ///< bytes of the whole field (count elements)
  int32_t count;                 ///< elements: 1, or the length of an array field (double[3])
  uint32_t flags;                ///< FT_PARAM_FLAG_*
  uint32_t since;                ///< FT_ABI_VERSION that added the field (for upgrading)
  int32_t element_type;          ///< POINTER: FT_PARAM_FLOAT, FT_PARAM_DOUBLE, FT_PARAM_OPAQUE or,
                                 ///< with element_kind >= 0, an array of that struct kind
  int32_t element_kind;          ///< FT_PARAMS_* of the pointed-to structs, or -1
  double default_value;          ///< what ft_*_params_init writes (pointers: 0 = NULL)
  double hard_min, hard_max;     ///< refused outside (see the EXCLUSIVE flags); validated by the
                                 ///< library for the fields the chosen method uses
  double soft_min, soft_max;     ///< the useful range, for sliders
  const char* unit;              ///< e.g. "scene units", "radians", "samples"; "" if none
  const char* label;             ///< a plain label in an artist's words, e.g. "Roughness"
  const char* doc;               ///< technical term, meaning and source, e.g. "Hurst exponent H
                                 ///< (Voss 1988): ..."
  uint64_t methods;              ///< bit m set: method m (the struct's `method` field) uses it;
                                 ///< FT_PARAM_ALL_METHODS for structs without a method
  int32_t enum_count;            ///< FT_PARAM_ENUM: items in `enum_items`; else 0
  const ft_param_enum_item* enum_items;
} ft_param_info;

/// Describes struct `kind`: its C name ("ft_terrain_params"), its size in
/// this library and its number of fields. Any output pointer may be NULL.
FT_API ft_status ft_params_describe(int32_t kind, const char** struct_name, uint32_t* struct_size,
                                    int32_t* field_count);
/// Row `index` (0 .. field_count - 1, in offset order) of struct `kind`.
/// `*out` points to static storage.
FT_API ft_status ft_params_field(int32_t kind, int32_t index, const ft_param_info** out);

#ifdef __cplusplus
}
#endif
#endif
