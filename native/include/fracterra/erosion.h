// SPDX-License-Identifier: GPL-3.0-or-later
/* fracterra erosion: fluvial (stream power + hillslope diffusion, Braun &
 * Willett 2013), hydraulic (virtual pipes, Mei et al. 2007) and thermal
 * (talus) erosion of a heightfield, and the maps artists texture by.
 * Heights and the grid spacing (world_size / (width - 1)) are world units. */
#ifndef FRACTERRA_EROSION_H
#define FRACTERRA_EROSION_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// The maps ft_erode can return, in world units.
typedef enum ft_erosion_map {
  FT_MAP_DRAINAGE_AREA = 0,  ///< upstream area (world units^2), multiple flow (Quinn 1991) on the eroded terrain, pits filled flat, flats crossed along random passage times to their outlets
  FT_MAP_SLOPE = 1,          ///< |grad z| (rise over run)
  FT_MAP_CURVATURE = 2,      ///< Laplacian of z (1 / world units; > 0 in hollows and channels)
  FT_MAP_WATER_DEPTH = 3,    ///< water left by the hydraulic passes (0 without them)
  FT_MAP_ERODED = 4,         ///< max(0, before - after)
  FT_MAP_DEPOSITED = 5,      ///< max(0, after - before)
  FT_MAP_COUNT = 6
} ft_erosion_map;

/// Fill with ft_erosion_params_init (every process off: counts 0; the defaults are the parameter
/// table's, `fracterra params`) or ft_erosion_preset. Counts are 0..100000; rates >= 0 and finite.
typedef struct ft_erosion_params {
  uint32_t struct_size;          ///< sizeof(ft_erosion_params)
  int32_t fluvial_steps;         ///< stream-power time steps; 0 = off
  double fluvial_dt;             ///< years per step (> 0)
  double erodibility;            ///< stream-power K (>= 0)
  double area_exponent;          ///< m in K A^m S (0..2, n = 1)
  double diffusion;              ///< hillslope diffusivity, world units^2 / yr (>= 0)
  double uplift;                 ///< world units / yr (>= 0); bounded edges erode towards the lowest input height
  int32_t hydraulic_iterations;  ///< virtual-pipe passes; 0 = off
  double hydraulic_dt;           ///< seconds per pass (1e-6..1)
  double rain;                   ///< water depth per pass, world units (>= 0)
  double evaporation;            ///< fraction per pass, 0..1
  double capacity;               ///< sediment capacity constant (>= 0)
  double dissolve;               ///< 0..1
  double deposit;                ///< 0..1
  int32_t thermal_iterations;    ///< talus passes; 0 = off
  double talus_degrees;          ///< angle of repose, 0..89
  double thermal_rate;           ///< fraction of the excess moved per pass, (0, 1]
  int32_t periodic;              ///< non-zero: the terrain tiles (eroded as a torus, stays seamless)
  int32_t threads;               ///< 0: all cores; output never depends on it
  ft_progress_fn progress;       ///< may be NULL; return non-zero to cancel (FT_ERR_CANCELLED)
  void* progress_user;
  int32_t uplift_follows_terrain;  ///< non-zero: each cell's uplift is `uplift` x its input height above the
                                   ///< lowest over the input's relief (the landform keeps its shape; ABI 2.12)
  /* ABI 2.14: the landscape model, in world units and years (docs/erosion.md). */
  double strength;               ///< 0..1: how far the run goes (the run is strength x duration)
  double duration;               ///< years of landscape evolution (channels, talus, fans); 0: off; presets set it
  double deposition;             ///< 0..1: share of the carried sediment a channel lays down per upstream area
                                 ///< (G of Yuan et al. 2019): 0 carves only, 1 builds wide fans
  double rainfall;               ///< world units of water per year on every cell (x rain_map)
  const float* erosion_mask;     ///< erosion_mask_width x erosion_mask_height values in [0, 1], row-major, corner
                                 ///< to corner, resampled bilinearly: where erosion acts (material still flows
                                 ///< out of it); NULL: everywhere
  int32_t erosion_mask_width;    ///< 2..65536 with a mask
  int32_t erosion_mask_height;   ///< 2..65536 with a mask
  const float* rain_map;         ///< as erosion_mask: where rain falls (x rainfall); NULL: everywhere
  int32_t rain_map_width;        ///< 2..65536 with a map
  int32_t rain_map_height;       ///< 2..65536 with a map
  /* ABI 2.21: the sea, a base level like the map's edge (erosion/sea.hpp). */
  int32_t sea;                   ///< FT_WATER_SEA_* (hydrology.h): every cell at or below the sea's level is sea:
                                 ///< rivers end there and cut no lower, what reaches it is carried away, the sea
                                 ///< floor stays
  double sea_level;              ///< FT_WATER_SEA_HEIGHT: the sea's height, world units
  double sea_fraction;           ///< FT_WATER_SEA_FRACTION: share of the samples below the sea, [0, 1)
  /* ABI 2.28 */
  double scree_years;            ///< years (> 0): the excess of a slope over the scree angle sheds with this
                                 ///< e-folding time (1e5; Scree Slopes 8e3)
} ft_erosion_params;

FT_API ft_status ft_erosion_params_init(ft_erosion_params* p);
/// A preset by its id or label ("gentle_valleys" / "Gentle Valleys",
/// "rugged_mountains", "badlands", "alluvial_fans", "scree_slopes"; the old ids
/// "valleys", "land", "rain" and "scree" are aliases of the first, second,
/// fourth and fifth) over the defaults.
FT_API ft_status ft_erosion_preset(const char* name, ft_erosion_params* p);
/// The preset for `terrain` (what `fracterra erode --preset` and the add-on's
/// Erode step use). Since ABI 2.14 the presets are in world units and years
/// and need no fitting: this is ft_erosion_preset after checking `terrain`.
/// (ABI 2.12)
FT_API ft_status ft_erosion_preset_fitted(const char* name, const ft_heightfield* terrain, ft_erosion_params* p);

/// Erodes `in` (grid spacing world_size / (width - 1); 1 when the world size is unknown). On
/// success `*out` is a new heightfield (free with ft_heightfield_free) and,
/// when `maps` is not NULL, maps[0 .. FT_MAP_COUNT - 1] are new heightfields
/// indexed by ft_erosion_map (free each). On failure every output is NULL.
FT_API ft_status ft_erode(const ft_heightfield* in, const ft_erosion_params* p, ft_heightfield** out,
                          ft_heightfield** maps);

/// Drainage statistics: Hack's law exponent h (main-stream length against
/// area) and the slope-area concavity theta, with their standard errors,
/// over channel cells of at least `min_area_cells` cells (>= 2; 20 is usual).
/// Cells of filled lakes count in neither; theta is fitted from the
/// slope-area plot's turnover (the hillslope-channel transition) up, when
/// that lies above `min_area_cells` (since 0.4.0; before, lakes counted in
/// Hack's law and theta was fitted from `min_area_cells`).
typedef struct ft_drainage_stats {
  double hack_h, hack_h_stderr, theta, theta_stderr;
  int32_t hack_bins, theta_bins;
} ft_drainage_stats;
FT_API ft_status ft_drainage_statistics(const ft_heightfield* hf, int32_t periodic, double min_area_cells,
                                        ft_drainage_stats* out);

#ifdef __cplusplus
}
#endif

#endif
