// SPDX-License-Identifier: GPL-3.0-or-later
// Rivers: single-flow receivers over the lakes' graded surface (steepest
// descent, erosion/flow_graph), drainage area down the stack, channel cells
// where the area passes min_area, segments between channel heads,
// confluences, lakes and outlets, Strahler orders (Strahler 1957) and
// streams, and the hydraulic geometry of Leopold & Maddock (1953).
#include <algorithm>
#include <cmath>
#include <omp.h>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "erosion/erosion.hpp"
#include "erosion/flow_graph.hpp"
#include "hydrology/hydrology.hpp"
#include "hydrology/hydrology_params.hpp"

namespace ft::hydrology {
namespace {

// Strahler's rule at a node: the largest incoming order, plus one when two
// or more branches carry it; 1 at a channel head.
struct OrderSum {
  int32_t max = 0, count = 0;
  void add(int32_t o) {
    if (o > max) max = o, count = 1;
    else if (o == max) ++count;
  }
  int32_t order() const { return max == 0 ? 1 : (count >= 2 ? max + 1 : max); }
};

}  // namespace

void validate(const HydrologyConfig& c, const Heightfield& hf) {
  check_ranges(hydrology_param_table(), &static_cast<const ft_hydrology_params&>(to_c(c)));
  if (hf.width() < 3 || hf.height() < 3)
    invalid("rivers need a terrain of at least 3 x 3 samples, got " + std::to_string(hf.width()) + " x " +
            std::to_string(hf.height()));
  for (size_t i = 0; i < hf.size(); ++i)
    if (!std::isfinite(hf.data()[i]))
      invalid("terrain height at sample " + std::to_string(i % hf.width()) + ", " + std::to_string(i / hf.width()) +
              " is " + format_number(hf.data()[i]) + ": rivers need finite heights");
  if (c.sea == Sea::kHeight) {
    const HeightStats s = hf.stats();
    if (!(c.sea_level >= s.min && c.sea_level <= s.max))
      invalid("sea_level must be within the terrain's heights [" + format_number(s.min) + ", " + format_number(s.max) +
              "], got " + format_number(c.sea_level));
  }
  if (c.sinks.size() % 2 != 0) invalid("sinks must be (x, y) pairs, got " + std::to_string(c.sinks.size()) + " numbers");
  const erosion::D8Grid g = erosion::grid_of(hf, c.periodic);
  const double wx = g.spacing * (g.width - 1), wy = g.spacing * (g.height - 1);
  for (size_t k = 0; k < c.sinks.size(); k += 2)
    if (!(c.sinks[k] >= 0 && c.sinks[k] <= wx && c.sinks[k + 1] >= 0 && c.sinks[k + 1] <= wy))
      invalid("sink " + std::to_string(k / 2) + " at (" + format_number(c.sinks[k]) + ", " +
              format_number(c.sinks[k + 1]) + ") must lie on the terrain, x in [0, " + format_number(wx) +
              "] and y in [0, " + format_number(wy) + "]");
  resolve_threads(c.threads);
}

double resolved_min_depth(const HydrologyConfig& c, const Heightfield& hf) {
  if (c.min_depth > 0) return c.min_depth;
  const HeightStats s = hf.stats();
  return kAutoDepth * (double(s.max) - double(s.min));
}

RiverNetwork extract_rivers(const Heightfield& hf, const HydrologyConfig& c) {
  validate(c, hf);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(resolve_threads(c.threads));
  struct Restore {
    int n;
    ~Restore() { omp_set_num_threads(n); }
  } restore{saved};

  RiverNetwork net;
  const erosion::D8Grid g = erosion::grid_of(hf, c.periodic);
  net.grid = g;
  const size_t n = g.size();
  const float* z = hf.data();
  const double cell_area = g.spacing * g.spacing;

  // 1. The sea and the lakes.
  const double sea_level = sea_level_of(c, hf);
  const std::vector<uint8_t> sea = erosion::sea_cells(g, z, sea_level);
  std::vector<int32_t> sinks;
  for (size_t k = 0; k < c.sinks.size(); k += 2)
    sinks.push_back(int32_t(std::lround(c.sinks[k + 1] / g.spacing)) * g.width +
                    int32_t(std::lround(c.sinks[k] / g.spacing)));
  c.progress.report(0.05);
  net.water = fill_lakes(g, z, sea, sinks, c.min_lake_area, resolved_min_depth(c, hf));
  Water& w = net.water;
  w.sea_level = sea_level;
  c.progress.report(0.3);

  // 2. Receivers over the graded surface (every non-base cell has a lower
  //    neighbour on it), the base levels their own receivers, and the area.
  erosion::FlowGraph graph;
  erosion::route_steepest(g, w.graded.data(), -1, graph);
  for (size_t i = 0; i < n; ++i)
    if (w.base[i]) graph.receiver[i] = int32_t(i), graph.length[i] = 0.0f;
  // Across flat ground the graded surface's epsilon steps say nothing
  // about where water goes (they ran one straight streak per gully to the
  // nearest edge, and along it): rivers there wander and join (plains.cpp).
  route_plains(g, w, c.min_area, graph);
  erosion::build_stack(g, graph);
  if (graph.chunk_start.back() != int32_t(n))  // every cell reaches a base level
    fail(FT_ERR_INTERNAL, "extract_rivers: the routing across flats left a cycle");
  std::vector<double> area;
  erosion::accumulate_area(g, graph, area);
  c.progress.report(0.5);

  // 3. Channel cells: land (not sea, not a lake) whose area passes min_area,
  //    counting only the area that falls on its way (a cell of a flat, not
  //    under water, adds none): on a plain the graded surface sends every
  //    cell straight to its nearest outlet, and the plain's own cells would
  //    start one parallel streak after another. Rivers from the slopes
  //    still cross it, one channel per valley.
  std::vector<double> falling(n, 0.0);
  for (size_t k = n; k-- > 0;) {
    const int32_t i = graph.stack[k];
    const int32_t r = graph.receiver[i];
    const bool flat = r != i && w.label[i] == kLand && !(w.level[i] > z[i]) && !(z[i] > z[r]);
    if (!flat) falling[i] += cell_area;
    if (r != i) falling[r] += falling[i];
  }
  std::vector<uint8_t> channel(n, 0);
  double largest = 0;
  for (size_t i = 0; i < n; ++i) {
    if (w.label[i] != kLand) continue;
    largest = std::max(largest, falling[i]);
    channel[i] = falling[i] >= c.min_area;
  }
  if (!std::any_of(channel.begin(), channel.end(), [](uint8_t v) { return v != 0; }))
    invalid("no river reaches " + format_number(std::ceil(c.min_area / cell_area)) + " cells (min_area " +
            format_number(c.min_area) + " world units^2 at " + format_number(cell_area) +
            " per cell); the largest drainage area on land is " + format_number(largest) +
            " world units^2: give a smaller min_area");

  // Unwrapped positions (periodic grids): each cell's offset from its tree's
  // base, so a river crossing the seam is one continuous line. Receivers come
  // before their donors in the stack.
  std::vector<std::array<double, 2>> offset(c.periodic ? n : 0, {0.0, 0.0});
  if (c.periodic)
    for (const int32_t i : graph.stack) {
      const int32_t r = graph.receiver[i];
      if (r == i) continue;
      const int32_t dx = i % g.width - r % g.width, dy = i / g.width - r / g.width;
      offset[i] = offset[r];
      if (dx > 1) offset[i][0] -= g.width * g.spacing;
      if (dx < -1) offset[i][0] += g.width * g.spacing;
      if (dy > 1) offset[i][1] -= g.height * g.spacing;
      if (dy < -1) offset[i][1] += g.height * g.spacing;
    }

  // 4. Segment starts: heads, confluences and lake outlets, upstream first;
  //    Strahler orders by cell, lakes passing on the order of their inflows.
  const int32_t nl = int32_t(w.lakes.size());
  std::vector<OrderSum> lake_in(static_cast<size_t>(nl));
  std::vector<int32_t> cell_order(n, 0);
  std::vector<int32_t> starts;
  std::vector<int32_t> start_of(n, -1);  // segment id starting at a cell
  std::vector<int32_t> from_lake(n, -1);
  for (size_t k = n; k-- > 0;) {
    const int32_t i = graph.stack[k];
    if (!channel[i]) continue;
    OrderSum in;
    int32_t branches = 0, lake = -1;
    for (int32_t d = graph.donor_start[i]; d < graph.donor_start[i + 1]; ++d) {
      const int32_t j = graph.donors[d];
      if (channel[j]) in.add(cell_order[j]), ++branches;
      else if (w.label[j] >= 0 && area[j] >= c.min_area) lake = w.label[j];
    }
    if (lake >= 0) in.add(lake_in[size_t(lake)].order()), ++branches, from_lake[i] = lake;
    cell_order[i] = in.order();
    const bool land_base = w.base[i] != 0;
    if (!land_base && (branches != 1 || lake >= 0)) {
      start_of[i] = int32_t(starts.size());
      starts.push_back(i);
    }
    const int32_t r = graph.receiver[i];
    if (r != i && w.label[r] >= 0) lake_in[size_t(w.label[r])].add(cell_order[i]);
  }
  c.progress.report(0.6);

  // 5. Segments: from each start down to the next start, the sea, a lake or
  //    a base level; the last vertex of one is the first of the next.
  std::vector<int32_t> cells;
  std::vector<std::array<double, 2>> offs;
  std::vector<double> half;
  for (size_t s = 0; s < starts.size(); ++s) {
    Segment seg;
    cells.assign(1, starts[s]);
    for (;;) {
      const int32_t i = cells.back();
      const int32_t r = graph.receiver[i];
      if (r == i) {  // a base level on land: the map's edge or a declared sink
        seg.end = (!c.periodic && g.on_edge(i % g.width, i / g.width)) ? RiverEnd::kEdge : RiverEnd::kSink;
        break;
      }
      cells.push_back(r);
      if (w.label[r] == kSea) { seg.end = RiverEnd::kSea; break; }
      if (w.label[r] >= 0) { seg.end = RiverEnd::kLake, seg.lake = w.label[r]; break; }
      if (start_of[r] >= 0) { seg.end = RiverEnd::kConfluence, seg.downstream = start_of[r]; break; }
    }
    seg.order = cell_order[starts[s]];
    seg.from_lake = from_lake[starts[s]];
    offs.resize(cells.size());
    half.resize(cells.size());
    for (size_t k = 0; k < cells.size(); ++k) {
      // The water of the cell a river ends in (sea, lake) is the last river
      // cell's: widths never jump at the mouth.
      const int32_t src = (k + 1 == cells.size() && w.label[cells[k]] != kLand) ? cells[k - 1] : cells[k];
      offs[k] = c.periodic ? offset[cells[k]] : std::array<double, 2>{0, 0};
      half[k] = 0.5 * c.width_coefficient * std::pow(area[src] * c.rain, c.width_exponent);
    }
    const PathVertices pv = river_path(g, w, cells, offs, half, c, uint32_t(s));
    seg.first_vertex = net.lines.vertex_count();
    seg.vertex_count = int64_t(pv.points.size());
    for (size_t v = 0; v < pv.points.size(); ++v) {
      const int32_t k = pv.source[v];
      const int32_t src = (size_t(k) + 1 == cells.size() && w.label[cells[size_t(k)]] != kLand) ? cells[size_t(k) - 1]
                                                                                            : cells[size_t(k)];
      const double q = area[src] * c.rain;
      const double width = c.width_coefficient * std::pow(q, c.width_exponent);
      net.lines.add(pv.points[v], 0.5 * width);
      net.discharge.push_back(q);
      net.width.push_back(width);
      net.depth.push_back(c.depth_coefficient * std::pow(q, c.depth_exponent));
      net.area.push_back(area[src]);
      if (v > 0) {
        const Vec3& a = pv.points[v - 1];
        seg.length += std::hypot(pv.points[v][0] - a[0], pv.points[v][1] - a[1]);
      }
    }
    net.lines.end_line();
    net.total_length += seg.length;
    net.segments.push_back(seg);
    if ((s & 255) == 0) c.progress.report(0.6 + 0.35 * double(s) / double(starts.size()));
  }
  // 6. Strahler streams: a segment continues the stream of the upstream
  //    segment of its own order (at most one has it, else the order would
  //    have grown), through a lake too. Segments come upstream first.
  std::vector<int32_t> continues(net.segments.size(), -1);
  std::vector<int32_t> lake_stream(size_t(nl), -1), lake_order(size_t(nl), 0);
  int32_t streams = 0;
  for (size_t s = 0; s < net.segments.size(); ++s) {
    Segment& seg = net.segments[s];
    if (continues[s] >= 0) seg.stream = continues[s];
    else if (seg.from_lake >= 0 && lake_order[size_t(seg.from_lake)] == seg.order) seg.stream = lake_stream[size_t(seg.from_lake)];
    else seg.stream = streams++;
    if (seg.downstream >= 0 && net.segments[size_t(seg.downstream)].order == seg.order)
      continues[size_t(seg.downstream)] = seg.stream;
    if (seg.end == RiverEnd::kLake && seg.order > lake_order[size_t(seg.lake)])
      lake_order[size_t(seg.lake)] = seg.order, lake_stream[size_t(seg.lake)] = seg.stream;
  }

  // 7. Lakes: outlets, the segment leaving each, shorelines.
  for (int32_t l = 0; l < nl; ++l) w.lakes[size_t(l)].outlet = -1;
  for (size_t i = 0; i < n; ++i) {
    const int32_t l = w.label[i];
    if (l < 0 || w.lakes[size_t(l)].outlet >= 0) continue;
    int32_t j = int32_t(i);
    while (w.label[j] == l && graph.receiver[j] != j) j = graph.receiver[j];
    w.lakes[size_t(l)].outlet = j;
  }
  for (size_t s = 0; s < net.segments.size(); ++s)
    if (net.segments[s].from_lake >= 0) w.lakes[size_t(net.segments[s].from_lake)].outlet_segment = int32_t(s);
  net.lake_rings = lake_rings(g, z, w);
  c.progress.report(1.0);
  return net;
}

}  // namespace ft::hydrology
