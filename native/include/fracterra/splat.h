// SPDX-License-Identifier: GPL-3.0-or-later
/* fracterra splat: weight maps (splat maps) and colour maps of a terrain for
 * game engines, Blender and POV-Ray, from one set of layer rules (ABI 2.19;
 * rules files read through the ABI: 2.22).
 *
 * Each layer (rock, grass, ...) has a rule: a weight times a band in height
 * (as a fraction of the terrain's height range, 0 lowest, 1 highest), a band
 * in slope (degrees) and, optionally, a "wet" condition on the erosion maps
 * (deposited thickness as a fraction of the height range, drainage area as
 * a fraction of the terrain's area). A band [min, max] with blend b rises
 * linearly from 0 at min - b/2 to 1 at min + b/2 (and falls likewise about
 * max); blend 0 is a hard edge (1 inside [min, max]). A layer whose rule
 * uses both deposit and flow takes the larger of the two (sediment lies
 * where it was laid down or where water runs). At each sample the layers'
 * weights are divided by their sum; where no rule gives any weight the first
 * layer takes it all. The integer maps are rounded by largest remainder so
 * that every sample's weights sum to exactly `total` (255 or 65535). */
#ifndef FRACTERRA_SPLAT_H
#define FRACTERRA_SPLAT_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// The rule of one layer. Fill with ft_splat_params_init; ranges in params.h
/// (FT_PARAMS_SPLAT).
typedef struct ft_splat_params {
  uint32_t struct_size;   ///< sizeof(ft_splat_params)
  const char* name;       ///< the layer's name ("rock"); unique within a rule set; may be NULL
  double height_min;      ///< band in height, fraction of the height range; default 0
  double height_max;      ///< default 1
  double height_blend;    ///< width of the band's soft edges (fraction); default 0
  double slope_min;       ///< band in slope, degrees; default 0
  double slope_max;       ///< default 90
  double slope_blend;     ///< degrees; default 0
  double deposit_min;     ///< deposited thickness / height range at which the layer starts; 0: unused
  double deposit_blend;   ///< its soft edge (same unit); default 0
  double flow_min;        ///< drainage area / terrain area at which the layer starts; 0: unused
  double flow_blend;      ///< its soft edge in decades of drainage area; default 0
  double weight;          ///< the layer's strength against the others; default 1
  double color[3];        ///< sRGB 0..1 for colour maps and materials; default mid grey
} ft_splat_params;

FT_API ft_status ft_splat_params_init(ft_splat_params* layer);

/// The built-in rule set: grass (by height), rock (by slope), sediment (by
/// deposit and flow), snow (by height and slope), in that order (R, G, B, A
/// of the first splat map). `*count` gets the number of layers; `layers`
/// (may be NULL to ask the count) holds `capacity` structs whose struct_size
/// the caller set. Names point to static storage.
FT_API ft_status ft_splat_default_layers(ft_splat_params* layers, int32_t capacity, int32_t* count);

/// The weights of `layer_count` (1..64) layers over `terrain`, as integers
/// that sum to exactly `total` (255 or 65535) at every sample: `out` holds
/// width * height * layer_count uint16 values, sample-major (sample i's
/// layers at out[i * layer_count ...]). `deposited` (world units) and
/// `drainage_area` (world units^2) are the erosion maps of the same size, or
/// NULL (their conditions then see 0). The slope is the terrain's own, with
/// its world size (1 per sample when unknown).
FT_API ft_status ft_splat_weights(const ft_heightfield* terrain, const ft_heightfield* deposited,
                                  const ft_heightfield* drainage_area, const ft_splat_params* layers,
                                  int32_t layer_count, int32_t total, uint16_t* out, size_t out_count);

/// The colour map by the same rules: sRGB 0..1, width * height * 3 floats,
/// the layers' colours mixed by their (unrounded) weights.
FT_API ft_status ft_splat_colors(const ft_heightfield* terrain, const ft_heightfield* deposited,
                                 const ft_heightfield* drainage_area, const ft_splat_params* layers,
                                 int32_t layer_count, float* rgb, size_t rgb_count);

/// The colour map as renderers that light in linear light take it (Blender's colour
/// attributes): ft_splat_colors' colours decoded to linear RGB (IEC 61966-2-1), with alpha 1,
/// width * height * 4 floats into `rgba` (ABI 2.25). Rows in parallel on up to `threads`
/// threads (0: all cores; 0..1024), the same bits on any count. `progress` (may be NULL) hears
/// the share of rows done from the calling thread; non-zero cancels (FT_ERR_CANCELLED; `rgba`
/// is then partly written).
FT_API ft_status ft_splat_colors_linear_rgba(const ft_heightfield* terrain, const ft_heightfield* deposited,
                                            const ft_heightfield* drainage_area, const ft_splat_params* layers,
                                            int32_t layer_count, int32_t threads, ft_progress_fn progress,
                                            void* progress_user, float* rgba, size_t rgba_count);

/// A rule set read from a rules JSON file ({"layers": [{"name": ..., fields of ft_splat_params}]}),
/// checked as `fracterra splat --rules` checks it (ABI 2.22), so every front end refuses the same
/// files with the same message (file, layer and field named).
typedef struct ft_splat_rules ft_splat_rules;

/// Reads and checks the rules file at `path` (UTF-8). On success `*out` owns the rules: release
/// them with ft_splat_rules_free. On failure `*out` is NULL and ft_last_error() names what is wrong
/// (FT_ERR_IO: unreadable; FT_ERR_FORMAT: not JSON; FT_ERR_INVALID_ARGUMENT: a bad field).
FT_API ft_status ft_splat_rules_read(const char* path, ft_splat_rules** out);

/// The layers of `rules`, as ft_splat_default_layers gives the built-in ones: `*count` gets the
/// number of layers; `layers` (may be NULL to ask the count) holds `capacity` structs whose
/// struct_size the caller set. Their names point into `rules`: valid until ft_splat_rules_free.
FT_API ft_status ft_splat_rules_layers(const ft_splat_rules* rules, ft_splat_params* layers, int32_t capacity,
                                       int32_t* count);

/// Releases rules from ft_splat_rules_read; NULL is a no-op.
FT_API void ft_splat_rules_free(ft_splat_rules* rules);

#ifdef __cplusplus
}
#endif
#endif
