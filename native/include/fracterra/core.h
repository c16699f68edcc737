/// @file fracterra/core.h
/// The conventions every fracterra C call shares: status codes, the
/// per-thread error message, versions, progress callbacks and the result
/// handles (heightfields, polyline sets). Made for ctypes: plain C types only.
#ifndef FRACTERRA_CORE_H
#define FRACTERRA_CORE_H

#include <stddef.h>
#include <stdint.h>

#if defined(FT_BUILDING_LIBRARY) && defined(_WIN32)
#define FT_API __declspec(dllexport)
#elif defined(FT_BUILDING_LIBRARY)
#define FT_API __attribute__((visibility("default")))
#else
#define FT_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/// ABI version: the major number changes when a struct or signature changes
/// incompatibly; the minor one when functions or trailing struct fields are
/// added. Bindings refuse a library whose major number differs from theirs.
#define FT_ABI_VERSION_MAJOR 2
/// 2.0: ft_hurst_result starts with struct_size; one name per concept (world_size_x/y,
/// has_sea/sea_level, octave_rotation, std_error, FT_FRACTALIZE_MIDPOINT); params.h, the
/// parameter tables. (1.1: ft_terrain_params.world_size; 1.2: the Mandelbrot fields and
/// FT_HURST_AUTO; ft_terrain_params keeps their layout, so its 1.x sizes are still accepted.)
/// The shared library's SOVERSION is this major number.
/// 2.1: erosion.h (ft_erode, its maps, ft_drainage_statistics).
/// 2.2: windows of a terrain (ft_terrain_extent, ft_terrain_generate_window(_lod)).
/// 2.3: raster.h (read and write by extension, ft_dem_refine).
/// 2.4: tiles.h (tile sets: ft_tileset_*, ft_tile_write); H of windows from increment sums (analysis.h).
/// 2.5: params.h describes ft_pov_scene_params, ft_pov_sweep_params, ft_hurst_params,
/// ft_clouds_params and ft_dem_refine_params; each accepts any older struct_size.
/// 2.6: landforms at the end of ft_terrain_params (levelling, height_offset, falloff,
/// falloff_width, edge_level, sea, sea_level, sea_fraction); FT_FALLOFF_*, FT_SEA_*.
/// 2.7: tile sets read back (ft_tileset_extent, ft_tileset_read_window).
/// 2.8: the erosion parameters are described (FT_PARAMS_EROSION in params.h).
/// 2.9: a custom falloff mask (FT_FALLOFF_CUSTOM; falloff_mask, falloff_mask_width and
/// falloff_mask_height at the end of ft_terrain_params).
/// 2.10: tile sets journal their finished tiles; a set's exact height range can
///      be computed per tile elsewhere (ft_tileset_open_deferred, ft_tile_height_range).
/// 2.11: ft_pov_scene_params.camera_margin and camera_center_v (described, so the camera's
/// ranges are checked once); camera_elevation_deg 0 = auto, by the scene's content
/// (FT_PARAM_FLAG_ZERO_IS_AUTO in params.h); 0 is ft_pov_scene_params_init's default.
/// 2.12: ft_erosion_preset_fitted (erosion.h); uplift_follows_terrain at the end of
///      ft_erosion_params.
/// 2.13: pipeline.h: ft_terrain_build (generate -> landform -> erode -> maps in one call, one
///      progress callback; a tiling terrain erodes as a torus of its true period),
///      ft_build_params (described: FT_PARAMS_BUILD), FT_EROSION_PRESET_*.
/// 2.14: the erosion landscape model in world units and years: strength, duration,
///      deposition, rainfall, erosion_mask (+ width, height) and rain_map (+ width,
///      height) at the end of ft_erosion_params; presets named for what they make
///      (the old ids stay as aliases); ft_erosion_preset_fitted no longer fits an uplift.
/// 2.15: hydrology.h: rivers, lakes and the sea (ft_rivers_extract, the ft_river_network
///      accessors, ft_rivers_carve; FT_PARAMS_HYDROLOGY describes ft_hydrology_params).
/// 2.17: a given camera, terrain colours and scene light at the end of ft_pov_scene_params
///      (camera_given, camera_location/direction/right/up, terrain_colors, has_scene_light,
///      sky_color, sun_color): the add-on's export shows Blender's view and material.
/// 2.18: planet.h: fractal planets (ft_planet_face, ft_planet_equirect, ft_planet_heights,
///      ft_planet_sea_height, ft_planet_mesh(_counts)); ft_planet_params (FT_PARAMS_PLANET).
/// 2.19: splat.h: splat (weight) maps and colour maps by layer rules (ft_splat_params, described:
///      FT_PARAMS_SPLAT; ft_splat_params_init, ft_splat_default_layers, ft_splat_weights,
///      ft_splat_colors).
/// 2.20: rivers as the pipeline's last stage: ft_terrain_build_rivers (pipeline.h) and
///      ft_build_params.rivers; a terrain that tiles gives rivers that wrap, in every front end;
///      ft_river_network_grid (the grid a network was traced on).
/// 2.21: the sea as erosion's base level: ft_erosion_params.sea, sea_level and sea_fraction.
/// 2.22: splat rules files read through the ABI (ft_splat_rules_read, ft_splat_rules_layers,
///      ft_splat_rules_free), so the add-on's material checks a file as the CLI does.
/// 2.23: planet.h: FT_PLANET_MIDPOINT (midpoint displacement on the cube-sphere), the icosphere
///      (ft_planet_icosphere(_counts)), the spherical-harmonic spectrum (ft_planet_power_spectrum,
///      ft_planet_spectrum_hurst).
/// 2.24: ft_build_features, ft_has_feature and ft_heightfield_formats: what this build has
///      (the Windows build has no GDAL, OpenEXR or OpenSubdiv; docs/windows.md).
/// 2.25: ft_splat_colors_linear_rgba (splat.h): the colour map as Blender's colour attribute
///      takes it, with progress and cancel.
#define FT_ABI_VERSION_MINOR 25
#define FT_ABI_VERSION ((FT_ABI_VERSION_MAJOR << 16) | FT_ABI_VERSION_MINOR)

/// Every exported function that can fail returns one of these.
typedef int32_t ft_status;
enum {
  FT_OK = 0,
  FT_ERR_INVALID_ARGUMENT = 1, ///< a parameter is out of range, NaN or NULL
  FT_ERR_OUT_OF_MEMORY = 2,    ///< an allocation failed
  FT_ERR_TOO_LARGE = 3,        ///< the request exceeds the documented memory cap
  FT_ERR_IO = 4,               ///< a file could not be opened, read or written
  FT_ERR_FORMAT = 5,           ///< a file is malformed or of an unsupported kind
  FT_ERR_CANCELLED = 6,        ///< the progress callback asked to stop
  FT_ERR_UNSUPPORTED = 7,      ///< the method or option is not available
  FT_ERR_INTERNAL = 8          ///< a bug: please report the message
};

/// (FT_ABI_VERSION_MAJOR << 16) | FT_ABI_VERSION_MINOR of the loaded library.
FT_API uint32_t ft_abi_version(void);
/// "major.minor.patch" of the library (the CMake project version); static storage.
FT_API const char* ft_version_string(void);
/// The message of the last failed call on this thread: what was wrong and what
/// is allowed. Valid until the next fracterra call on this thread; never NULL
/// ("" after a successful call).
FT_API const char* ft_last_error(void);
/// A short name for a status code ("FT_ERR_INVALID_ARGUMENT"); static storage.
FT_API const char* ft_status_name(ft_status status);
/// The optional libraries this build has, space-separated: "gdal openexr opensubdiv"
/// on Linux, "" for Windows (docs/windows.md). A call that needs a missing one
/// returns FT_ERR_UNSUPPORTED naming it. Static storage.
FT_API const char* ft_build_features(void);
/// 1 if this build has `feature` ("gdal", "openexr" or "opensubdiv"), else 0 (NULL too).
FT_API int32_t ft_has_feature(const char* feature);
/// The heightfield formats this build reads and writes, for messages and
/// menus: "PNG, PGM, NPY, RAW16, GeoTIFF, OpenEXR and every raster GDAL reads"
/// on Linux, "PNG, PGM, NPY and RAW16" without GDAL and OpenEXR. Static storage.
FT_API const char* ft_heightfield_formats(void);

/// Progress callback for long calls: `fraction` grows from 0 to 1. Return
/// non-zero to cancel; the call then returns FT_ERR_CANCELLED and frees
/// everything it made. May be called from the calling thread only.
typedef int32_t (*ft_progress_fn)(void* user, double fraction);

/// Memory cap for one result, in bytes (default 8 GiB, also limited by the
/// machine's available memory). Requests above it fail with FT_ERR_TOO_LARGE
/// before anything is allocated.
FT_API uint64_t ft_memory_cap(void);
/// Sets the memory cap; 0 restores the default.
FT_API void ft_set_memory_cap(uint64_t bytes);

/* ---------------------------------------------------------------------------
 * Heightfields: float32 samples, row-major, width x height, row 0 first.
 * Row index grows with y (image row 0 is y = 0), column index with x.
 * ------------------------------------------------------------------------- */
typedef struct ft_heightfield ft_heightfield;

/// A new heightfield of the given size filled with `data` (width * height
/// floats, may be NULL for zeros). Caller frees with ft_heightfield_free.
FT_API ft_status ft_heightfield_create(int32_t width, int32_t height, const float* data,
                                       ft_heightfield** out);
FT_API int32_t ft_heightfield_width(const ft_heightfield* hf);
FT_API int32_t ft_heightfield_height(const ft_heightfield* hf);
/// Pointer to width * height contiguous floats, owned by the handle and valid
/// until it is freed. NULL for a NULL handle.
FT_API const float* ft_heightfield_data(const ft_heightfield* hf);
/// Writable pointer to the same samples.
FT_API float* ft_heightfield_data_mut(ft_heightfield* hf);
/// Copies the samples into `dst`, which holds `count` floats (must be at least
/// width * height).
FT_API ft_status ft_heightfield_copy(const ft_heightfield* hf, float* dst, size_t count);
/// Minimum, maximum, mean and standard deviation of the samples (any may be NULL).
FT_API ft_status ft_heightfield_stats(const ft_heightfield* hf, double* min, double* max,
                                      double* mean, double* std);
/// Extent along x in scene units that the heightfield stands for (0 if unknown).
FT_API double ft_heightfield_world_size(const ft_heightfield* hf);
/// Sets the extent along x in scene units (finite, > 0).
FT_API ft_status ft_heightfield_set_world_size(ft_heightfield* hf, double world_size);
/// Frees the handle; NULL is a harmless no-op.
FT_API void ft_heightfield_free(ft_heightfield* hf);

/* ---------------------------------------------------------------------------
 * Polyline sets: one or more polylines sharing a vertex array. Vertices are
 * float64 xyz (2D lines have z = 0), each with a radius (for tapering; 0 if
 * the generator has none). Polyline i spans vertices offsets[i] to
 * offsets[i+1] - 1.
 * ------------------------------------------------------------------------- */
typedef struct ft_polylines ft_polylines;

/// A new set from `vertex_count` xyz triples, optional radii (NULL: zeros),
/// and `line_count + 1` offsets (NULL with line_count 1: one line of all).
FT_API ft_status ft_polylines_create(const double* xyz, const double* radii, int64_t vertex_count,
                                     const int64_t* offsets, int64_t line_count,
                                     ft_polylines** out);
FT_API int64_t ft_polylines_line_count(const ft_polylines* p);
FT_API int64_t ft_polylines_vertex_count(const ft_polylines* p);
/// 3 * vertex_count doubles, owned by the handle.
FT_API const double* ft_polylines_xyz(const ft_polylines* p);
/// vertex_count doubles, owned by the handle.
FT_API const double* ft_polylines_radii(const ft_polylines* p);
/// line_count + 1 offsets, owned by the handle.
FT_API const int64_t* ft_polylines_offsets(const ft_polylines* p);
/// Frees the handle; NULL is a harmless no-op.
FT_API void ft_polylines_free(ft_polylines* p);

#ifdef __cplusplus
}
#endif
#endif
