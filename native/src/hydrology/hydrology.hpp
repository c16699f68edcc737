// SPDX-License-Identifier: GPL-3.0-or-later
// Hydrology: the water of a terrain as objects. Above erosion/ (whose flow
// graph, Priority-Flood and sea it reuses) and polyline/ (Nikulin's FPL for
// meanders):
//   lakes.cpp     depressions filled to their spill level, labelled, measured;
//   lake_rings.cpp shorelines by marching squares;
//   plains.cpp    rivers across flat ground: they wander and gather;
//   rivers.cpp    channel heads, segments, Strahler orders, hydraulic geometry;
//   river_paths.cpp grid steps smoothed away, meanders, the downhill check;
//   carve.cpp     the terrain lowered along the rivers.
// World units throughout: x = column x spacing, y = row x spacing.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/heightfield.hpp"
#include "core/polyline_set.hpp"
#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/flow_graph.hpp"
#include "erosion/sea.hpp"

namespace ft::hydrology {

using erosion::Sea;  // erosion/sea.hpp: the sea is a base level of erosion too
enum class RiverEnd : int32_t { kConfluence = 0, kSea = 1, kLake = 2, kEdge = 3, kSink = 4 };

struct HydrologyConfig {
  double min_area = 0.1;           // world units^2 at a channel head
  Sea sea = Sea::kNone;
  double sea_level = 0.0;
  double sea_fraction = 0.3;
  double min_lake_area = 0.01;     // world units^2
  double rain = 1.0;               // Q = A x rain
  double width_coefficient = 0.03, width_exponent = 0.5;   // w = a Q^b
  double depth_coefficient = 0.006, depth_exponent = 0.4;  // d = c Q^f
  int32_t smoothing = 3;
  int32_t meander_depth = 0;
  double meander_spread = 0.3;
  uint64_t seed = 1;
  double tolerance = 1e-4;
  bool periodic = false;
  int threads = 0;
  double min_depth = 0;            // world units; 0: kAutoDepth of the relief (resolved_min_depth)
  std::vector<double> sinks;       // x, y pairs, world units
  Progress progress;
};

// The minimum water depth with min_depth = 0: this share of the relief.
inline constexpr double kAutoDepth = 0.01;

// A river drawn as a ribbon (Blender's river curve, the POV-Ray scenes'
// ribbons): a flat ellipse as wide as the river and this fraction of that
// high, centred on the water surface. carve() keeps the ground under it
// this fraction of the half width under the water, so its top stands clear.
inline constexpr double kRibbonFlat = 0.3;

// Per cell: kLand, kSea, or the index of a lake (>= 0).
inline constexpr int32_t kLand = -1, kSea = -2;

struct Lake {
  double level = 0, area = 0, volume = 0;
  int32_t outlet = -1;          // the cell it spills into (not in the lake)
  int32_t cells = 0;
  int32_t outlet_segment = -1;
  int64_t first_ring = 0, ring_count = 0;
  int64_t outer_rings = 0;      // its first rings are shorelines (one per deep part), the rest islands
};

// The surface water: what lakes.cpp computes from the terrain.
struct Water {
  std::vector<float> level;     // the filled surface: max(z, spill level) (lakes flat at their level)
  std::vector<float> graded;    // the same plus Priority-Flood's epsilon steps: every non-base cell drains
  std::vector<int32_t> label;   // kLand, kSea or a lake index
  std::vector<uint8_t> base;    // 1: a base level (edge of a bounded map, sea, declared sink)
  std::vector<Lake> lakes;
  double sea_level = 0;         // NaN without a sea
  double min_depth = 0;         // resolved (world units): lakes cover their cells by more
};

struct Segment {
  int64_t first_vertex = 0, vertex_count = 0;
  int32_t order = 1, downstream = -1;
  RiverEnd end = RiverEnd::kConfluence;
  int32_t lake = -1, from_lake = -1, stream = -1;
  double length = 0;
};

struct RiverNetwork {
  erosion::D8Grid grid;
  PolylineSet lines;                 // one per segment; radius = width / 2
  std::vector<double> discharge, width, depth, area;  // per vertex
  std::vector<Segment> segments;
  Water water;
  PolylineSet lake_rings;            // closed shorelines, z = level
  double total_length = 0;
};

// Throws naming the parameter and its range (the table's ranges are checked
// by from_c; these are the ones that depend on the terrain).
void validate(const HydrologyConfig& c, const Heightfield& hf);

// The sea's height (NaN without a sea); its cells are erosion::sea_cells.
inline double sea_level_of(const HydrologyConfig& c, const Heightfield& hf) {
  return erosion::sea_height(c.sea, c.sea_level, c.sea_fraction, hf);
}

// min_depth in world units: c.min_depth, or kAutoDepth of hf's relief when 0.
double resolved_min_depth(const HydrologyConfig& c, const Heightfield& hf);

// Fills every depression to its spill level (Priority-Flood from the base
// levels: the bounded map's edge, the sea, the declared sinks, or a periodic
// map's lowest sample) and labels each filled depression (8-connected cells
// under one level) of at least min_lake_area, some of it deeper than
// min_depth, as a lake; the others are puddles rivers run through.
Water fill_lakes(const erosion::D8Grid& g, const float* z, const std::vector<uint8_t>& sea,
                 const std::vector<int32_t>& sinks, double min_lake_area, double min_depth);

// Receivers across flats (land cells with no lower neighbour on the filled
// surface, not base levels): each river that comes onto a flat with at
// least min_area of water is laid, the largest first, along the cheapest
// path over random step costs (stream kRiverPlains) to the nearest laid
// water, an outlet of the flat or a river laid before, so rivers wander and
// join there; the flat's other cells drain to the nearest laid water. The
// receivers off the flats are the graded surface's (graph, routed by
// route_steepest); the new ones point into the flat or to its outlets, so
// the graph stays a forest. Serial, in a fixed order. Returns the number of
// cells re-routed. Leaves graph's stack stale: build it again.
int64_t route_plains(const erosion::D8Grid& g, const Water& w, double min_area, erosion::FlowGraph& graph);

// Shorelines of every lake as closed rings (outer ring first, then islands),
// where the ground lies water.min_depth under the lake's level (so the lake's
// polygon never lies flush with the ground), in world units at that level;
// sets each lake's first_ring / ring_count.
PolylineSet lake_rings(const erosion::D8Grid& g, const float* z, Water& water);

// Everything: sea, lakes, rivers, orders, geometry. Throws "no river reaches N
// cells" when no cell's area passes min_area.
RiverNetwork extract_rivers(const Heightfield& hf, const HydrologyConfig& c);

// The vertices of one river path through the cells `cells` (upstream first):
// grid steps smoothed away, meanders added, every vertex's surface height at
// most its upstream neighbour's plus the tolerance. `offsets` unwrap a
// periodic path (world units added to each cell's position). Returns the
// points with z = the surface; `source` gets, for each point, the index in
// `cells` whose values (area, width) it carries.
struct PathVertices {
  std::vector<Vec3> points;
  std::vector<int32_t> source;
};
PathVertices river_path(const erosion::D8Grid& g, const Water& w, const std::vector<int32_t>& cells,
                        const std::vector<std::array<double, 2>>& offsets, const std::vector<double>& half_width,
                        const HydrologyConfig& c, uint32_t line_id);

// The surface (water level) at a world point, bilinear, wrapped on a periodic grid.
double surface_at(const erosion::D8Grid& g, const std::vector<float>& level, double x, double y);

// The terrain lowered along the rivers: under each river vertex's surface by
// its depth x cos^2(pi r / 2) at r = distance / half width (half width at
// least 0.75 spacing, so a narrow river still has a bed), and every corner of
// a grid cell the river's ribbon covers (its half width around the line) to
// kRibbonFlat x the half width under the segment's water surface extended
// along it, so the ground's triangles lie that far under the whole ribbon; never
// below the sea's level (net.water.sea_level; a bed that reached it would be
// sea); lake and sea cells keep their heights.
Heightfield carve(const Heightfield& terrain, const RiverNetwork& net);

}  // namespace ft::hydrology
