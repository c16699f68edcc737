// SPDX-License-Identifier: GPL-3.0-or-later
// River networks and lakes as files (see river_files.hpp).
#include "hydrology/river_files.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/polyline_io.hpp"
#include "io/vector_io.hpp"

namespace ft::hydrology {
namespace {

const char* end_name(RiverEnd e) {
  switch (e) {
    case RiverEnd::kConfluence: return "confluence";
    case RiverEnd::kSea: return "sea";
    case RiverEnd::kLake: return "lake";
    case RiverEnd::kEdge: return "edge";
    case RiverEnd::kSink: return "sink";
  }
  return "?";
}

std::string rivers_csv(const RiverNetwork& net) {
  std::string out = "# x,y,z,radius,discharge,width,depth,area,segment,order\n";
  char buf[320];
  for (size_t s = 0; s < net.segments.size(); ++s) {
    const Segment& seg = net.segments[s];
    if (s > 0) out += "\n";
    for (int64_t v = seg.first_vertex; v < seg.first_vertex + seg.vertex_count; ++v) {
      const Vec3& p = net.lines.points[size_t(v)];
      std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%zu,%d\n", p[0], p[1], p[2],
                    net.lines.radii[size_t(v)], net.discharge[size_t(v)], net.width[size_t(v)],
                    net.depth[size_t(v)], net.area[size_t(v)], s, seg.order);
      out += buf;
    }
  }
  return out;
}

nlohmann::json lakes_json(const RiverNetwork& net) {
  nlohmann::json lakes = nlohmann::json::array();
  const auto& g = net.grid;
  for (const Lake& l : net.water.lakes) {
    nlohmann::json rings = nlohmann::json::array();
    for (int64_t r = l.first_ring; r < l.first_ring + l.ring_count; ++r) {
      nlohmann::json ring = nlohmann::json::array();
      for (int64_t v = net.lake_rings.line_begin(r); v < net.lake_rings.line_end(r); ++v)
        ring.push_back({net.lake_rings.points[size_t(v)][0], net.lake_rings.points[size_t(v)][1]});
      rings.push_back(ring);
    }
    lakes.push_back({{"level", l.level},
                     {"area", l.area},
                     {"volume", l.volume},
                     {"cells", l.cells},
                     {"outlet", {(l.outlet % g.width) * g.spacing, (l.outlet / g.width) * g.spacing}},
                     {"outlet_segment", l.outlet_segment},
                     {"rings", rings}});
  }
  return lakes;
}

std::string rivers_json(const RiverNetwork& net) {
  nlohmann::json lines = nlohmann::json::array();
  for (const Segment& seg : net.segments) {
    nlohmann::json pts = nlohmann::json::array(), radii = nlohmann::json::array();
    nlohmann::json q = nlohmann::json::array(), w = nlohmann::json::array(), d = nlohmann::json::array(),
                   a = nlohmann::json::array();
    for (int64_t v = seg.first_vertex; v < seg.first_vertex + seg.vertex_count; ++v) {
      const Vec3& p = net.lines.points[size_t(v)];
      pts.push_back({p[0], p[1], p[2]});
      radii.push_back(net.lines.radii[size_t(v)]);
      q.push_back(net.discharge[size_t(v)]);
      w.push_back(net.width[size_t(v)]);
      d.push_back(net.depth[size_t(v)]);
      a.push_back(net.area[size_t(v)]);
    }
    lines.push_back({{"points", pts},          {"radii", radii},         {"discharge", q},
                     {"width", w},             {"depth", d},             {"area", a},
                     {"order", seg.order},     {"stream", seg.stream},   {"downstream", seg.downstream},
                     {"end", end_name(seg.end)}, {"lake", seg.lake},     {"from_lake", seg.from_lake},
                     {"length", seg.length}});
  }
  nlohmann::json doc = {{"polylines", lines}, {"lakes", lakes_json(net)}};
  if (std::isfinite(net.water.sea_level)) doc["sea_level"] = net.water.sea_level;
  return doc.dump() + "\n";
}

io::VectorLayer river_layer(const RiverNetwork& net) {
  io::VectorLayer L;
  L.name = "rivers";
  L.fields = {"segment", "order", "stream", "downstream", "lake", "from_lake", "length", "discharge", "width",
              "depth", "area"};
  L.integer = {true, true, true, true, true, true, false, false, false, false, false};
  L.string_fields = {"end"};
  for (size_t s = 0; s < net.segments.size(); ++s) {
    const Segment& seg = net.segments[s];
    const size_t last = size_t(seg.first_vertex + seg.vertex_count - 1);
    L.geometry.push_back({std::vector<Vec3>(net.lines.points.begin() + seg.first_vertex,
                                            net.lines.points.begin() + std::ptrdiff_t(last) + 1)});
    // Discharge, width, depth and area at the mouth (the largest).
    L.values.push_back({double(s), double(seg.order), double(seg.stream), double(seg.downstream), double(seg.lake),
                        double(seg.from_lake), seg.length, net.discharge[last], net.width[last], net.depth[last],
                        net.area[last]});
    L.strings.push_back({end_name(seg.end)});
  }
  return L;
}

// Even-odd: is p inside the closed ring?
bool inside_ring(const std::vector<Vec3>& ring, const Vec3& p) {
  bool in = false;
  for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++)
    if ((ring[i][1] > p[1]) != (ring[j][1] > p[1]) &&
        p[0] < (ring[j][0] - ring[i][0]) * (p[1] - ring[i][1]) / (ring[j][1] - ring[i][1]) + ring[i][0])
      in = !in;
  return in;
}

io::VectorLayer lake_layer(const RiverNetwork& net) {
  io::VectorLayer L;
  L.name = "lakes";
  L.polygons = true;
  L.fields = {"lake", "level", "area", "volume", "cells", "outlet_segment"};
  L.integer = {true, false, false, false, true, true};
  for (size_t k = 0; k < net.water.lakes.size(); ++k) {
    const Lake& l = net.water.lakes[k];
    if (l.ring_count == 0) continue;  // a lake around the whole torus has no inside
    auto ring = [&](int64_t r) {
      return std::vector<Vec3>(net.lake_rings.points.begin() + net.lake_rings.line_begin(r),
                               net.lake_rings.points.begin() + net.lake_rings.line_end(r));
    };
    // A Polygon per shoreline (a lake has one per part deeper than the
    // minimum depth) with the islands inside it as holes.
    const int64_t outers = std::max<int64_t>(1, l.outer_rings), islands = l.first_ring + outers;
    for (int64_t o = l.first_ring; o < islands; ++o) {
      std::vector<std::vector<Vec3>> rings{ring(o)};
      for (int64_t r = islands; r < l.first_ring + l.ring_count; ++r)
        if (outers == 1 || inside_ring(rings[0], net.lake_rings.points[size_t(net.lake_rings.line_begin(r))]))
          rings.push_back(ring(r));
      L.geometry.push_back(std::move(rings));
      L.values.push_back({double(k), l.level, l.area, l.volume, double(l.cells), double(l.outlet_segment)});
    }
  }
  return L;
}

}  // namespace

void write_rivers(const RiverNetwork& net, const GeoReference& geo, const std::string& path) {
  const std::string ext = io::extension_of(path);
  if (ext == ".csv") io::write_file_atomically(path, rivers_csv(net));
  else if (ext == ".json") io::write_file_atomically(path, rivers_json(net));
  else if (ext == ".geojson") io::write_vector_layers({river_layer(net)}, geo, net.grid.spacing, path);
  else if (ext == ".gpkg") io::write_vector_layers({river_layer(net), lake_layer(net)}, geo, net.grid.spacing, path);
  else invalid("'" + path + "': unsupported river format (use .csv, .json, .geojson or .gpkg)");
}

void write_lakes(const RiverNetwork& net, const GeoReference& geo, const std::string& path) {
  const std::string ext = io::extension_of(path);
  if (ext == ".json") io::write_file_atomically(path, nlohmann::json{{"lakes", lakes_json(net)}}.dump() + "\n");
  else if (ext == ".geojson" || ext == ".gpkg") io::write_vector_layers({lake_layer(net)}, geo, net.grid.spacing, path);
  else invalid("'" + path + "': unsupported lake format (use .json, .geojson or .gpkg)");
}

WaterScene read_water_json(const std::string& path) {
  WaterScene w;
  const std::string text = io::read_file(path);
  w.rivers = io::decode_polylines_json(text, path);
  const nlohmann::json doc = nlohmann::json::parse(text);  // valid: decoded above
  if (doc.contains("lakes")) {
    const auto& lakes = doc["lakes"];
    auto bad = [&](const std::string& why) { fail(FT_ERR_FORMAT, "'" + path + "': " + why); };
    if (!lakes.is_array()) bad("\"lakes\" must be an array");
    for (const auto& l : lakes) {
      if (!l.is_object() || !l.contains("level") || !l["level"].is_number() || !l.contains("rings") ||
          !l["rings"].is_array())
        bad("each lake needs a \"level\" and \"rings\"");
      WaterScene::LakeShape shape;
      shape.level = l["level"].get<double>();
      for (const auto& r : l["rings"]) {
        std::vector<Vec3> ring;
        if (!r.is_array()) bad("a ring must be an array of [x, y]");
        for (const auto& p : r) {
          if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
            bad("a ring's points must be [x, y] numbers");
          ring.push_back({p[0].get<double>(), p[1].get<double>(), shape.level});
        }
        shape.rings.push_back(std::move(ring));
      }
      w.lakes.push_back(std::move(shape));
    }
  }
  return w;
}

}  // namespace ft::hydrology
