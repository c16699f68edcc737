// SPDX-License-Identifier: GPL-3.0-or-later
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
/// The minor number: what each one added is in CHANGES.md (ABI history).
#define FT_ABI_VERSION_MINOR 28
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
