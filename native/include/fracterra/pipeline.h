// SPDX-License-Identifier: GPL-3.0-or-later
/// @file fracterra/pipeline.h
/// One call for a whole terrain: generate -> landform -> erode -> maps ->
/// rivers, with one progress callback across the stages (ABI 2.13; rivers 2.20). The CLI's
/// `terrain --erode` and the Blender add-on both call it, so a setting gives
/// the same bits in every front end.
#ifndef FRACTERRA_PIPELINE_H
#define FRACTERRA_PIPELINE_H

#include "core.h"
#include "erosion.h"
#include "hydrology.h"
#include "terrain.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Erosion presets (ft_build_params.erosion_preset), named for what they make;
/// the value names are ft_erosion_preset's names or their aliases ("valleys", ...).
enum {
  FT_EROSION_PRESET_NONE = 0,     ///< none: the erosion params as given
  FT_EROSION_PRESET_VALLEYS = 1,  ///< Gentle Valleys: soft rock, long river valleys
  FT_EROSION_PRESET_RAIN = 2,     ///< Alluvial Fans: sediment spread where valleys open out
  FT_EROSION_PRESET_SCREE = 3,    ///< Scree Slopes: steep slopes shed to their talus angle
  FT_EROSION_PRESET_LAND = 4,     ///< Rugged Mountains: incised valleys, sharp ridges, scree
  FT_EROSION_PRESET_BADLANDS = 5  ///< Badlands: dense gullies in soft rock
};

/// Parameters of ft_terrain_build. Fill with ft_build_params_init, then set
/// `terrain` (and `erosion` and/or `erosion_preset` to erode). Described by
/// ft_params_field(FT_PARAMS_BUILD, ...).
typedef struct ft_build_params {
  uint32_t struct_size;              ///< sizeof(ft_build_params); set by _init
  int32_t threads;                   ///< 0: all cores; 1..1024; used by every stage (the stages' own
                                     ///< `threads` are ignored). The output never depends on it.
  const ft_terrain_params* terrain;  ///< the terrain and its landform; required. Its progress is ignored.
  const ft_erosion_params* erosion;  ///< NULL: no erosion (unless erosion_preset); else the erosion
                                     ///< settings. Their `periodic`, `threads` and progress are ignored:
                                     ///< a terrain that tiles is eroded as a torus of its true period
                                     ///< (midpoint and additions: size - 1, the last row and column
                                     ///< repeating the first, and still so after erosion; others: size).
  int32_t erosion_preset;            ///< FT_EROSION_PRESET_*: fitted to the generated terrain (as
                                     ///< ft_erosion_preset_fitted), it sets the pass counts and every
                                     ///< value it changes from the defaults; the rest comes from
                                     ///< `erosion` (or the defaults when NULL). Default NONE.
  ft_progress_fn progress;           ///< one fraction 0..1 across all stages; non-zero cancels; may be NULL
  void* progress_user;
  const ft_hydrology_params* rivers; ///< (2.20) the rivers stage's settings (ft_terrain_build_rivers);
                                     ///< NULL: the defaults. Their `periodic`, `threads` and progress are
                                     ///< ignored: a terrain that tiles is routed as the torus it is
                                     ///< eroded on (rivers wrap; midpoint and additions: size - 1 per
                                     ///< side, the network's water mask too). A terrain with a sea of its
                                     ///< own (ft_terrain_params.sea) gives the rivers that sea, at the
                                     ///< height the landform flattened it (plus 1e-3 of the relief:
                                     ///< erosion lays sediment on its floor); the rivers'
                                     ///< sea fields count only for a terrain without one.
} ft_build_params;

/// Fills `p` with the defaults (no terrain: set p->terrain). `p` must not be NULL.
FT_API ft_status ft_build_params_init(ft_build_params* p);
/// Builds the terrain `p` describes. On success `*out` owns a new
/// heightfield (free with ft_heightfield_free); when `maps` is not NULL,
/// maps[0 .. FT_MAP_COUNT - 1] are new heightfields indexed by ft_erosion_map
/// (erosion.h), the maps of the result (eroded or not; free each). On
/// failure or cancellation every output is NULL and nothing is leaked.
FT_API ft_status ft_terrain_build(const ft_build_params* p, ft_heightfield** out, ft_heightfield** maps);
/// ft_terrain_build, then its rivers, lakes and sea (ABI 2.20): `rivers` (not
/// NULL) receives the network of the built terrain (free with
/// ft_river_network_free), traced with p->rivers under the pipeline's rules
/// (above). `*out` is the terrain carved along its rivers (ft_rivers_carve: each bed its river's
/// depth under the water, never below the sea; 2.27), so no river lies flush with the ground.
/// `maps` may be NULL. On failure or cancellation every output is NULL.
FT_API ft_status ft_terrain_build_rivers(const ft_build_params* p, ft_heightfield** out, ft_heightfield** maps,
                                         ft_river_network** rivers);
/// The samples [x0, x0 + width) x [y0, y0 + height) of what ft_terrain_build(p) makes, heights and
/// (maps: NULL or FT_MAP_COUNT handles) every map, bit-identical to the same samples of the whole
/// (ABI 2.26), so a tile set of windows has no seams. `*out`'s world size is the window's share of
/// the terrain's. Refused, with the reason: a window outside ft_terrain_extent(p->terrain, 0, ...),
/// the methods without windows (spectral synthesis: one global FFT), a sea given as a fraction
/// (its level is a quantile of the whole). An erosion mask or rain map spans the whole terrain,
/// corner to corner, as for ft_terrain_build. An eroded window's heights take the memory of the
/// window grown by the erosion's reach (a hundred-odd samples) and of the landscape model's coarse
/// grid; its maps (maps not NULL) those of the window grown by one sample, but the drainage area,
/// which is global: it reads the whole eroded terrain (computed in bands, about 45 bytes a sample
/// of the whole). The expert passes (fluvial_steps,
/// hydraulic_iterations, thermal_iterations) read the whole grid: their windows are the whole,
/// cropped. On failure every output is NULL.
FT_API ft_status ft_terrain_build_window(const ft_build_params* p, int64_t x0, int64_t y0, int32_t width,
                                         int32_t height, ft_heightfield** out, ft_heightfield** maps);

/// What the pipeline's later stages need of a terrain beside its heights and world size (ABI 2.27):
/// whether it tiles and its own sea. ft_terrain_build_world reports it; ft_terrain_erode and
/// ft_terrain_rivers take it, so that a terrain kept (in a file, in numpy) and eroded or traced
/// later gets the same bits as ft_terrain_build's erode and rivers stages give it.
typedef struct ft_terrain_world {
  uint32_t struct_size;    ///< sizeof(ft_terrain_world); set by _init
  int32_t period_overlap;  ///< -1: it does not tile; else it tiles, and its last `period_overlap` rows
                           ///< and columns repeat the first (midpoint and additions: 1; others: 0)
  double sea_level;        ///< the height of its own flat sea (the landform's), or NaN: none
} ft_terrain_world;

/// Fills `w` with a terrain that does not tile and has no sea (-1, NaN).
FT_API ft_status ft_terrain_world_init(ft_terrain_world* w);
/// ft_terrain_build_rivers (`rivers` may be NULL: no rivers stage) that also reports the built
/// terrain's world in `world` (not NULL): what ft_terrain_erode and ft_terrain_rivers need to
/// continue the pipeline on it (ABI 2.27).
FT_API ft_status ft_terrain_build_world(const ft_build_params* p, ft_heightfield** out, ft_heightfield** maps,
                                        ft_river_network** rivers, ft_terrain_world* world);
/// The pipeline's erode stage on a terrain already made (ABI 2.27): `terrain` eroded as ft_terrain_build
/// erodes the terrain it generates, with p->erosion and p->erosion_preset (fitted to `terrain`) by the
/// same rule, p->threads and p->progress; p->terrain and p->rivers are not read (may be NULL). With
/// `world` (not NULL) the terrain's rules replace the erosion's periodic and sea fields: a terrain that
/// tiles erodes as the torus of its true period (its repeated rows and columns left out and copied back
/// after), its sea is the base level. With `world` NULL the erosion's own fields hold (as `fracterra
/// erode --in`). A terrain without a world size (0) erodes in a world of 10 units. Outputs as
/// ft_terrain_build's; so ft_terrain_erode(p, build of p without erosion, its world) equals
/// ft_terrain_build(p) bit for bit.
FT_API ft_status ft_terrain_erode(const ft_build_params* p, const ft_heightfield* terrain,
                                  const ft_terrain_world* world, ft_heightfield** out, ft_heightfield** maps);
/// The pipeline's rivers stage on a terrain already made (ABI 2.27): the rivers, lakes and sea of
/// `terrain` with p->rivers (NULL: the defaults) and p->threads under ft_terrain_build_rivers' rules,
/// the terrain's from `world` (NULL: the rivers' own periodic and sea fields hold): a terrain that
/// tiles is routed as its torus, its own sea is the rivers' sea. `*rivers` receives the network.
FT_API ft_status ft_terrain_rivers(const ft_build_params* p, const ft_heightfield* terrain,
                                   const ft_terrain_world* world, ft_river_network** rivers);

#ifdef __cplusplus
}
#endif
#endif
