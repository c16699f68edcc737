// SPDX-License-Identifier: GPL-3.0-or-later
/* fracterra hydrology: rivers, lakes and the sea of a heightfield as objects.
 * Depressions are filled to their spill level (Priority-Flood, Barnes et al.
 * 2014): a filled depression of at least min_lake_area is a lake (level,
 * area, volume, outlet, shoreline polygon). Cells below a sea level and
 * connected to the map's edge are sea. Rivers start where the single-flow
 * drainage area over the filled surface passes min_area, follow the receivers
 * to the sea, a lake, the map's edge or a declared sink, and carry per vertex
 * the discharge Q = area x rain, the width a Q^b and the depth c Q^f
 * (Leopold & Maddock 1953). Every segment (between channel heads,
 * confluences, lakes and outlets) has a Strahler order; confluences are
 * shared vertices. Coordinates are world units: x = column x spacing,
 * y = row x spacing, spacing = world_size / (width - 1) (1 when unknown);
 * z is the water surface (the terrain with its depressions filled). Water is
 * shown only where it has depth: a lake is the cells its level covers by more
 * than min_depth (1% of the relief by default: a shallower one is passed
 * through), and its shoreline runs where the ground lies min_depth below the
 * level, so no water surface lies flush with the ground (ABI 2.27). (ABI 2.15) */
#ifndef FRACTERRA_HYDROLOGY_H
#define FRACTERRA_HYDROLOGY_H

#include "core.h"

#ifdef __cplusplus
extern "C" {
#endif

/// Where the sea is (the values of terrain.h's FT_SEA_*).
typedef enum ft_water_sea {
  FT_WATER_SEA_NONE = 0,      ///< no sea
  FT_WATER_SEA_HEIGHT = 1,    ///< below sea_level (world units)
  FT_WATER_SEA_FRACTION = 2   ///< below the height with sea_fraction of the samples below it
} ft_water_sea;

/// Fill with ft_hydrology_params_init; ranges in params.h (FT_PARAMS_HYDROLOGY).
typedef struct ft_hydrology_params {
  uint32_t struct_size;     ///< sizeof(ft_hydrology_params)
  double min_area;          ///< drainage area at a channel head, world units^2 (> 0); default 0.1
  int32_t sea;              ///< FT_WATER_SEA_*; default FT_WATER_SEA_NONE
  double sea_level;         ///< FT_WATER_SEA_HEIGHT: within the terrain's heights
  double sea_fraction;      ///< FT_WATER_SEA_FRACTION: [0, 1); default 0.3
  double min_lake_area;     ///< smaller filled depressions are passed through, world units^2; default 0.01
  double rain;              ///< discharge per unit of drainage area (Q = A x rain); default 1
  double width_coefficient; ///< a in w = a Q^b, world units; default 0.03
  double width_exponent;    ///< b; default 0.5
  double depth_coefficient; ///< c in d = c Q^f, world units; default 0.006
  double depth_exponent;    ///< f; default 0.4
  int32_t smoothing;        ///< passes of smoothing that take the grid steps away; default 3
  int32_t meander_depth;    ///< FPL levels between vertices, 0: no meanders; default 0
  double meander_spread;    ///< FPL spread (amplitude bounded by the width); default 0.3
  uint64_t seed;            ///< the meanders' seed
  double tolerance;         ///< a vertex may be this much above its upstream neighbour, world units; default 1e-4
  int32_t periodic;         ///< non-zero: the terrain tiles; rivers wrap across its edges
  int32_t threads;          ///< 0: all cores; output never depends on it
  const double* sinks;      ///< sink_count (x, y) world points that are declared sinks; may be NULL
  int32_t sink_count;
  ft_progress_fn progress;  ///< may be NULL; return non-zero to cancel
  void* progress_user;
  double min_depth;         ///< (2.27) a depression no deeper than this is not a lake, and shorelines
                            ///< run where the water is this deep (world units, >= 0); 0 (default):
                            ///< 1% of the terrain's relief (max - min height)
} ft_hydrology_params;

FT_API ft_status ft_hydrology_params_init(ft_hydrology_params* p);

/// How a river segment ends.
typedef enum ft_river_end {
  FT_RIVER_CONFLUENCE = 0,  ///< joins a larger river (its last vertex is the other's first)
  FT_RIVER_SEA = 1,
  FT_RIVER_LAKE = 2,
  FT_RIVER_EDGE = 3,        ///< leaves the map (bounded terrains)
  FT_RIVER_SINK = 4         ///< a declared sink (or a periodic terrain's lowest sample)
} ft_river_end;

typedef struct ft_river_segment {
  int64_t first_vertex, vertex_count;  ///< its vertices in the network's polylines
  int32_t order;            ///< Strahler order
  int32_t downstream;       ///< the segment it flows into, -1 at an end
  int32_t end;              ///< ft_river_end
  int32_t lake;             ///< FT_RIVER_LAKE: the lake it ends in; else -1
  int32_t from_lake;        ///< the lake whose outlet it starts at, else -1
  int32_t stream;           ///< its Strahler stream (segments of one order in a row)
  double length;            ///< world units along its vertices
} ft_river_segment;

typedef struct ft_lake {
  double level;             ///< water surface height
  double area;              ///< world units^2 (cells x spacing^2)
  double volume;            ///< world units^3: sum of (level - z) x spacing^2
  double outlet_x, outlet_y;  ///< where it spills, world units
  int32_t outlet_segment;   ///< the river that leaves it, -1 if none reaches min_area
  int32_t cells;
  int64_t first_ring, ring_count;  ///< its shoreline rings in the lake polylines: first the outer ones
                                   ///< (one per part deeper than min_depth, largest first), then its
                                   ///< islands
} ft_lake;

typedef struct ft_river_network ft_river_network;

/// Rivers and lakes of `terrain`. Fails with a message (FT_ERR_INVALID_ARGUMENT)
/// when no cell reaches min_area ("no river reaches N cells"), for non-finite
/// heights, or a sea level outside the heights.
FT_API ft_status ft_rivers_extract(const ft_heightfield* terrain, const ft_hydrology_params* p,
                                   ft_river_network** out);
FT_API void ft_river_network_free(ft_river_network* net);
FT_API int32_t ft_river_network_segment_count(const ft_river_network* net);
FT_API int32_t ft_river_network_lake_count(const ft_river_network* net);
/// The grid the network was traced on (ABI 2.20): the terrain's, or the torus
/// of a tiling terrain built by ft_terrain_build_rivers (one sample smaller a
/// side for midpoint and additions). Its water mask has width x height cells.
FT_API ft_status ft_river_network_grid(const ft_river_network* net, int32_t* width, int32_t* height);
/// The rivers as polylines (one per segment, radius = half the width); a new
/// handle, free with ft_polylines_free.
FT_API ft_status ft_river_network_polylines(const ft_river_network* net, ft_polylines** out);
/// Per vertex of the polylines (count = their vertex count): 0 discharge, 1 width, 2 depth, 3 drainage area.
FT_API ft_status ft_river_network_vertex_values(const ft_river_network* net, int32_t which, double* out,
                                                int64_t count);
FT_API ft_status ft_river_network_segments(const ft_river_network* net, ft_river_segment* out, int32_t count);
FT_API ft_status ft_river_network_lakes(const ft_river_network* net, ft_lake* out, int32_t count);
/// The minimum water depth the network was traced with (ABI 2.27): min_depth, or 1% of
/// the terrain's relief when that was 0. Front ends cut their sea and lake surfaces to
/// where the water is deeper than this.
FT_API ft_status ft_river_network_min_depth(const ft_river_network* net, double* out);
/// Lake shorelines (closed rings, world units, z = the level, where the ground lies
/// min_depth under it); free with ft_polylines_free.
FT_API ft_status ft_river_network_lake_rings(const ft_river_network* net, ft_polylines** out);
/// The rivers as drawn (ABI 2.28): the network's lines cut where a river's ribbon (its
/// half width to each side, square to the flow, flat at its ends) would reach into a
/// lake's shoreline rings, each part a line of its own; radius = half width. Render
/// geometry: ft_river_network_polylines keeps the whole lines, through the lakes.
/// Free with ft_polylines_free.
FT_API ft_status ft_river_network_ribbon_lines(const ft_river_network* net, ft_polylines** out);
/// Per cell: the lake index, -1 land, -2 sea (count = width x height). A lake's cells are
/// all its level floods; its rings enclose those deeper than min_depth.
FT_API ft_status ft_river_network_water_mask(const ft_river_network* net, int32_t* out, int64_t count);
/// The terrain lowered along each river to its depth over its width (a smooth
/// cos^2 profile under the water surface), and under the river's ribbon (0.3 x its
/// width high, centred on the water) to 0.3 x its half width under the water, so
/// the ribbon stands clear of the ground's triangles (2.28); never below the sea's
/// level (2.27); lakes and sea are left as they are.
FT_API ft_status ft_rivers_carve(const ft_heightfield* terrain, const ft_river_network* net, ft_heightfield** out);
/// Measures of a network (ABI 2.27), as `fracterra rivers --stats` and `analyze --rivers` report
/// them: Horton's ratios over its Strahler streams, drainage density, Hack's h.
typedef struct ft_network_measures {
  uint32_t struct_size;            ///< set by the caller to sizeof(ft_network_measures)
  int32_t horton_orders;           ///< highest Strahler order (0: no Horton ratios)
  int32_t horton_fitted_orders;    ///< orders in the ratios' fits
  int32_t hack_points;
  double bifurcation_ratio;        ///< R_b
  double bifurcation_ratio_stderr; ///< the standard error of log R_b
  double length_ratio;             ///< R_l
  double length_ratio_stderr;      ///< the standard error of log R_l
  double total_length;             ///< world units
  double land_area;                ///< world units^2: cells neither sea nor lake
  double drainage_density;         ///< total length / land area (1 / world units)
  double hack_h;                   ///< L ~ A^h: longest upstream length against area, per segment mouth
  double hack_h_stderr;
  int64_t segments;
  int64_t lakes;
  int64_t vertices;
  int32_t ends[5];                 ///< segments ending at a confluence, the sea, a lake, the edge, a sink
  int32_t reserved0;
  int64_t streams[32];             ///< N_k, streams of order k + 1 (k < horton_orders, at most 32)
  double mean_length[32];          ///< L_k, their mean length (world units)
} ft_network_measures;

FT_API ft_status ft_river_network_measures(const ft_river_network* net, ft_network_measures* out);
/// Writes the network to `path` as `fracterra rivers --out` does (ABI 2.27), by its extension:
/// .csv, .json, .geojson or .gpkg (rivers and lakes; the last two need a build with GDAL). With
/// `lakes_only` non-zero, the lakes alone as `--lakes` writes them (.geojson, .gpkg or .json).
/// `terrain` (may be NULL) gives the georeference: GeoJSON and GeoPackage are then in its CRS
/// and map coordinates. Written atomically.
FT_API ft_status ft_river_network_write(const ft_river_network* net, const ft_heightfield* terrain, const char* path,
                                        int32_t lakes_only);

#ifdef __cplusplus
}
#endif

#endif
