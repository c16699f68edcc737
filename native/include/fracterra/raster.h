// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/raster.h
/// Heightfields to and from files by extension (.png, .pgm, .npy, .tif as a
/// Cloud-Optimized GeoTIFF, .exr, .raw/.r16 with a sidecar JSON; reading
/// also takes any raster GDAL reads: .hgt, .asc, .vrt, ...), and the
/// refinement of a real DEM from its own samples. See docs/gis.md.
#ifndef FRACTERRA_RASTER_H
#define FRACTERRA_RASTER_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// What ft_heightfield_read does with nodata samples (the band's nodata
/// value, and NaN).
enum {
  FT_NODATA_REFUSE = 0,  ///< fail with FT_ERR_FORMAT and the count (the default)
  FT_NODATA_FILL = 1,    ///< fill by GDAL's inverse-distance fill; valid samples unchanged
  FT_NODATA_KEEP = 2     ///< keep them as NaN (ft_dem_refine then picks a window without them)
};

/// Reads `path` (UTF-8) into a new heightfield (*out; free with
/// ft_heightfield_free). The world size comes from the pixel size of a
/// georeferenced raster (degrees turned into metres), or from what fracterra
/// recorded. Sizes are checked against the memory cap before allocating.
/// `nodata` is FT_NODATA_*. On failure *out is NULL.
FT_API ft_status ft_heightfield_read(const char* path, int32_t nodata, ft_heightfield** out);

/// Writes `hf` to `path` in the format its extension names, atomically (a
/// temporary file renamed into place: a failure leaves no partial file and
/// keeps an existing one). A heightfield read from a georeferenced raster, or
/// refined from one, is written georeferenced to .tif.
FT_API ft_status ft_heightfield_write(const ft_heightfield* hf, const char* path);

/// Parameters of ft_dem_refine; fill with ft_dem_refine_params_init.
typedef struct ft_dem_refine_params {
  uint32_t struct_size;     ///< sizeof(ft_dem_refine_params); set by _init
  int32_t levels_added;     ///< K, 1..12: the window's side grows 2^K times; default 2
  double hurst;             ///< H in [0, 0.99], or < 0: measured on the DEM (default -1)
  double sigma;             ///< vertical scale > 0, or <= 0: from the DEM's one-pixel increments (default -1)
  uint64_t seed;            ///< default 1
  int32_t method;           ///< FT_TERRAIN_MIDPOINT (default) or FT_TERRAIN_ADDITIONS
  int32_t window_x;         ///< window's top-left sample, or -1 (default): the valid window nearest the centre
  int32_t window_y;         ///< as window_x
  int32_t window_side;      ///< 2^m + 1, or 0 (default): the largest without nodata
  int32_t threads;          ///< 0: all cores; output never depends on it
  ft_progress_fn progress;  ///< optional; may cancel
  void* progress_user;
} ft_dem_refine_params;

/// What ft_dem_refine chose and measured.
typedef struct ft_dem_refine_report {
  uint32_t struct_size;     ///< set by the caller to sizeof(ft_dem_refine_report)
  int32_t window_x, window_y, window_side;
  double hurst;             ///< H used
  double hurst_stderr;      ///< standard error of the measured H (0 when given)
  double sigma;             ///< sigma used
  double increment_variance;///< the DEM's mean squared increment at one pixel (V1)
  int32_t hurst_measured, sigma_measured;
} ft_dem_refine_report;

FT_API void ft_dem_refine_params_init(ft_dem_refine_params* p);

/// Refines a DEM (may hold NaN where it has no data): a (2^m + 1)^2 window of
/// it becomes the reference grid of midpoint displacement (or additions),
/// its values kept exactly at their nodes, and K levels are added. *out is
/// (2^(m + K) + 1)^2, georeferenced when the DEM was. `report` may be NULL.
FT_API ft_status ft_dem_refine(const ft_heightfield* dem, const ft_dem_refine_params* p, ft_heightfield** out,
                               ft_dem_refine_report* report);

#ifdef __cplusplus
}
#endif

#endif
