// SPDX-License-Identifier: GPL-3.0-or-later
// Erosion: fractal terrains become land. The landscape model (landscape.cpp)
// runs first: channels, talus and fans in world units and years, solved at a
// fixed cell size of the terrain's width / kModelCells and refined to the
// terrain's own grid, so every resolution gets the same landform. Then the
// expert passes, whose counts are in grid steps, in this order:
//   fluvial    stream-power incision + hillslope diffusion, implicit and O(n)
//              per time step (Braun & Willett 2013, "FastScape");
//   hydraulic  water, suspended sediment, erosion, deposition and
//              evaporation on the grid (the virtual-pipe model of Mei, Decaudin
//              & Hu 2007), sediment moved in flux form so mass is conserved;
//   thermal    material above the talus angle slides to lower neighbours.
// and the maps artists texture by, in world units. Every pass updates all
// cells from the previous state (Jacobi order) or runs serially along the
// stack, so the result is the same on any thread count. Periodic terrains
// are eroded as a torus and stay seamless.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/buffer.hpp"
#include "core/heightfield.hpp"
#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/flat_resolution.hpp"
#include "erosion/sea.hpp"

namespace ft::erosion {

inline constexpr int32_t kMaxErosionSteps = 100000;

// The largest |height| (world units) erosion takes, so the relief is at most
// twice it. The implicit solves multiply heights by factors up to
// kMaxSolveFactor (1e20) and add them in float: 1e15 keeps every product
// below 1e35, a thousandth of FLT_MAX (3.4e38). Beyond, a height of 1e38
// overflowed the fluvial solve to inf - inf = NaN and its routing never
// ended (issue 25). Any real terrain is far inside: 1e15 is Everest in
// units of 10 picometres.
inline constexpr double kMaxErosionHeight = 1e15;
// The largest factor an implicit solve applies (stream power's K dt A^m / L,
// diffusion's D dt / spacing^2): a factor f moves a height to within 1 / f
// of the relief of its target, so beyond 1e20 (reached only by absurd
// rates, which made it inf and the heights NaN) the result no longer changes.
inline constexpr float kMaxSolveFactor = 1e20f;

struct FluvialConfig {
  int32_t steps = 0;          // time steps; 0 = off
  double dt = 1000.0;         // years per step
  double erodibility = 2e-4;  // stream-power K (1/yr for m = 0.5, areas in world units^2)
  double area_exponent = 0.5; // m (slope exponent n = 1: the implicit solve is exact)
  double diffusion = 1e-7;    // hillslope diffusivity (world units^2 / yr); 0 = none (1e-7 km^2/yr = 0.1 m^2/yr)
  double uplift = 0.0;        // uplift rate (world units / yr) of every cell (not a periodic grid's sink)
  bool uplift_follows_terrain = false;  // each cell's rate x its input height above the lowest / the relief
};

struct HydraulicConfig {
  int32_t iterations = 0;     // passes; 0 = off
  double dt = 0.02;           // seconds per pass
  double rain = 0.01;         // water depth added per pass (world units)
  double evaporation = 0.02;  // fraction of the water evaporated per pass, 0..1
  double capacity = 1.0;      // sediment capacity constant Kc
  double dissolve = 0.3;      // fraction of the capacity deficit taken from the bed per pass, 0..1
  double deposit = 0.3;       // fraction of the excess sediment laid down per pass, 0..1
  double min_tilt = 0.05;     // smallest sin(tilt) in the capacity, so flats still carry
  double max_erosion = 0.0;   // largest bed lowering per pass and cell (0: spacing / 100)
};

struct ThermalConfig {
  int32_t iterations = 0;     // passes; 0 = off
  double talus_degrees = 33.0;  // angle of repose
  double rate = 0.5;          // fraction of the excess moved per pass, (0, 1]
};

// A map over the whole terrain, corner to corner (erosion_mask, rain_map).
struct MapInput {
  const float* values = nullptr;  // null: 1 everywhere
  int32_t width = 0, height = 0;
};

// The landscape model (landscape.cpp); its erodibility, area exponent,
// diffusion and talus angle are the fluvial and thermal ones.
struct ModelConfig {
  double strength = 0.5;     // 0..1, the run is strength x duration
  double duration = 0.0;     // years; 0: off
  double deposition = 0.5;   // G: share of the carried sediment laid down per upstream area
  double rainfall = 1.0;     // world units / yr on every cell (x the rain map)
  // The excess of a slope over the scree angle sheds with this e-folding
  // time (years): a run wears cliffs back in proportion to its length
  // instead of cutting every steep slope at once.
  double scree_years = 1e5;
};

// The model's working grid: every terrain is eroded at this cell size first
// (a wider one then refined, a narrower one resampled back to its samples).
inline constexpr int32_t kModelCells = 256;
// Largest side of an erosion mask or rain map.
inline constexpr int32_t kMaxMapSide = 65536;

struct ErosionConfig {
  ModelConfig model;
  MapInput erosion_mask, rain_map;
  FluvialConfig fluvial;
  HydraulicConfig hydraulic;
  ThermalConfig thermal;
  // The sea (sea.hpp): its cells are base levels that no process changes.
  Sea sea = Sea::kNone;
  double sea_level = 0.0;
  double sea_fraction = 0.3;
  bool periodic = false;
  int threads = 0;
  Progress progress;
};

// Maps on the terrain's grid, in world units.
struct ErosionMaps {
  Heightfield drainage_area;  // upstream area of each cell (world units^2), multiple flow on the filled result
  Heightfield slope;          // |grad z| (rise over run)
  Heightfield curvature;      // Laplacian of z (1 / world units; > 0 in hollows and channels)
  Heightfield water_depth;    // water left by the hydraulic pass (0 when it did not run)
  Heightfield eroded;         // max(0, before - after)
  Heightfield deposited;      // max(0, after - before)
  // Every map, in the order above: for what is done to each alike.
  std::array<Heightfield*, 6> all() {
    return {&drainage_area, &slope, &curvature, &water_depth, &eroded, &deposited};
  }
};

// Bookkeeping of the material-moving passes, for the conservation checks.
struct MassBudget {
  double carried_out = 0.0;   // volume (world units^3) that left at the edges
  double detached = 0.0;      // volume the landscape model took from the bed (its model grid)
  double deposited = 0.0;     // volume it laid down again
  // Volume the one-cell pits were lifted by (one_cell_pits.hpp; on the
  // model's grid when it is the terrain's own): from no bed, so the change
  // of the terrain's volume is deposited - detached + filled_pits there.
  double filled_pits = 0.0;
};

// Grid of a heightfield: spacing = world_size / (width - 1), or 1 when the
// world size is unknown.
D8Grid grid_of(const Heightfield& hf, bool periodic);

// Throws FT_ERR_INVALID_ARGUMENT naming the parameter and its range (from
// the table, erosion_params.cpp), a map of the wrong size or with values
// outside [0, 1], a grid smaller than 3 x 3, heights that are not finite or
// beyond +-kMaxErosionHeight, a total uplift (rate x dt x steps) beyond it.
void validate(const ErosionConfig& c, const Heightfield& hf);
// What validate checks of the settings alone (not of the terrain).
void validate_settings(const ErosionConfig& c);

// A map resampled bilinearly to the grid (empty for a null map).
std::vector<float> resample_map(const MapInput& m, int32_t width, int32_t height);

// The landscape model on the terrain's grid: `in` eroded into `out` (both
// g.size(); they may not overlap), coarse to fine (landscape.cpp,
// landscape_window.hpp), the samples at or below `sea_level` (NaN: none)
// kept as the sea. `budget` may be null.
// `model` (may be null) receives the model's run (landscape_window.hpp).
struct LandscapeModel;
void landscape(const D8Grid& g, const float* in, float* out, const ErosionConfig& c, double sea_level,
               MassBudget* budget, const Progress& progress, LandscapeModel* model = nullptr);

// The processes one by one, in place. `budget` may be null.
void fluvial(const D8Grid& g, float* z, const FluvialConfig& c, const Progress& progress);
// With `weight` (null: 1 everywhere; values in [0, 1]) the flux between two
// neighbours is scaled by the smaller of their weights: creep only where
// they let it, and a cell of weight 0 keeps its height.
void hillslope_diffusion(const D8Grid& g, float* z, double diffusivity_dt, const float* weight = nullptr);
// What fluvial() adds to each cell per step: the uplift, uniform or following
// the input `z0`; 0 at a periodic grid's sink; empty without uplift.
std::vector<float> uplift_per_step(const D8Grid& g, const float* z0, const FluvialConfig& c);
void hydraulic(const D8Grid& g, float* z, const HydraulicConfig& c, float* water_out, MassBudget* budget,
               const Progress& progress);
void thermal(const D8Grid& g, float* z, const ThermalConfig& c, const Progress& progress);

// Slope and curvature by central differences (one-sided at bounded edges).
// `progress` hears each quarter of the rows.
void slope_curvature(const D8Grid& g, const float* z, float* slope, float* curvature,
                     const Progress& progress = Progress());

// The surface the maps' drainage area runs on (terrain_maps.cpp): `out`
// with the heights nearer 0 than half a float step at its largest height
// set to 0, every depression filled flat to its spill (fill_closed_basins)
// and its flats graded (resolve_flats). `progress` hears both parts.
struct DrainageSurface {
  Buffer<float> z;
  int32_t sink = -1;  // a torus's outlet (periodic_sink), else -1
  FlatGrading flats;
};
// `frame` (may be null): g is a rectangle of frame->whole (resolve_flats).
DrainageSurface drainage_surface(const D8Grid& g, const float* out, const Progress& progress = Progress(),
                                 const FlatFrame* frame = nullptr);

// The maps' drainage area of `out` (world units^2, as float) into
// `area_out` (g's size; it may be `out`): multiple flow over
// drainage_surface. It reads the whole grid (water crosses any window), the
// one map that does.
void drainage_area_map(const D8Grid& g, const float* out, float* area_out, const Progress& progress = Progress());

// The eroded and deposited depths of `cells` samples, `out` against `in`
// plus `lifted` (empty: none): each sample's own, so a window's are the
// whole's.
void depth_maps(const float* in, const float* out, const std::vector<float>& lifted, int64_t cells, float* eroded,
                float* deposited);

// The maps of `out`, eroded from `in` (terrain_maps.cpp): drainage area,
// slope, curvature, and the eroded and deposited depths against `in` plus
// `lifted` (the uplift the run added to each cell; empty: none), into
// `maps` (allocated, of the grid's size; water_depth is left as it is). The
// same bits on any thread count. `progress` rises in steps of at most about
// a 30th of it; a cancel stops it (FT_ERR_CANCELLED). With `coarse` (may be
// null) the drainage area is by pieces (block_drainage.hpp), else of the whole.
struct CoarseFlow;
void erosion_maps(const D8Grid& g, const float* in, const float* out, const std::vector<float>& lifted,
                  ErosionMaps& maps, const Progress& progress, const CoarseFlow* coarse = nullptr);

// The whole pipeline: returns the eroded terrain; fills `maps` if not null.
Heightfield erode(const Heightfield& in, const ErosionConfig& c, ErosionMaps* maps, MassBudget* budget = nullptr);

}  // namespace ft::erosion
