// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/polyline_io.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace ft::io {
namespace {

void check_vertex(const Vec3& p, double r, const std::string& where) {
  if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]) || !std::isfinite(r))
    fail(FT_ERR_FORMAT, where + ": coordinates must be finite numbers");
}

}  // namespace

std::string encode_polylines_csv(const PolylineSet& set) {
  std::string out = "# x,y,z,radius\n";
  char buf[128];
  for (int64_t i = 0; i < set.line_count(); ++i) {
    if (i > 0) out += "\n";
    for (int64_t v = set.line_begin(i); v < set.line_end(i); ++v) {
      const Vec3& p = set.points[size_t(v)];
      std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%.17g\n", p[0], p[1], p[2], set.radii[size_t(v)]);
      out += buf;
    }
  }
  return out;
}

std::string encode_polylines_json(const PolylineSet& set) {
  nlohmann::json lines = nlohmann::json::array();
  for (int64_t i = 0; i < set.line_count(); ++i) {
    nlohmann::json pts = nlohmann::json::array(), radii = nlohmann::json::array();
    for (int64_t v = set.line_begin(i); v < set.line_end(i); ++v) {
      const Vec3& p = set.points[size_t(v)];
      pts.push_back({p[0], p[1], p[2]});
      radii.push_back(set.radii[size_t(v)]);
    }
    lines.push_back({{"points", pts}, {"radii", radii}});
  }
  return nlohmann::json{{"polylines", lines}}.dump() + "\n";
}

PolylineSet decode_polylines_csv(const std::string& text, const std::string& name) {
  PolylineSet set;
  std::istringstream in(text);
  std::string line;
  long lineno = 0;
  int extra = 0;  // columns after the radius named by the header
  while (std::getline(in, line)) {
    ++lineno;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos) {
      set.end_line();
      continue;
    }
    if (line[first] == '#') {
      // A header naming columns after x,y,z,radius (a river file's discharge,
      // width, ...): those columns are read past.
      if (line.compare(first, 15, "# x,y,z,radius,") == 0)
        extra = int(std::count(line.begin() + std::ptrdiff_t(first), line.end(), ',')) - 3;
      continue;
    }
    double v[4] = {0, 0, 0, 0};
    int n = 0;
    const char* s = line.c_str() + first;
    while (n < 5 + extra) {
      char* end = nullptr;
      const double x = std::strtod(s, &end);
      if (end == s) break;
      if (n < 4) v[n] = x;
      ++n;
      while (*end == ' ' || *end == '\t') ++end;
      if (*end == ',') s = end + 1;
      else { s = end; break; }
    }
    while (*s == ' ' || *s == '\t') ++s;
    const std::string where = "'" + name + "' line " + std::to_string(lineno);
    if (n < 2 || n > 4 + extra || (extra > 0 && n != 4 + extra) || *s != '\0')
      fail(FT_ERR_FORMAT, where + (extra > 0 ? ": expected " + std::to_string(4 + extra) + " columns as the header names"
                                             : std::string(": expected x,y[,z[,radius]]")));
    const Vec3 p{v[0], v[1], v[2]};
    check_vertex(p, v[3], where);
    set.add(p, v[3]);
  }
  set.end_line();
  return set;
}

PolylineSet decode_polylines_json(const std::string& text, const std::string& name) {
  PolylineSet set;
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    fail(FT_ERR_FORMAT, "'" + name + "' is not valid JSON: " + e.what());
  }
  auto bad = [&](const std::string& why) { fail(FT_ERR_FORMAT, "'" + name + "': " + why); };
  if (!doc.is_object() || !doc.contains("polylines") || !doc["polylines"].is_array())
    bad("expected an object with a \"polylines\" array");
  for (const auto& l : doc["polylines"]) {
    if (!l.is_object() || !l.contains("points") || !l["points"].is_array()) bad("each polyline needs \"points\"");
    const auto& pts = l["points"];
    const bool has_r = l.contains("radii") && l["radii"].is_array();
    if (has_r && l["radii"].size() != pts.size()) bad("\"radii\" must have one entry per point");
    for (size_t k = 0; k < pts.size(); ++k) {
      const auto& q = pts[k];
      if (!q.is_array() || q.size() < 2 || q.size() > 3) bad("a point must be [x, y] or [x, y, z]");
      for (const auto& c : q)
        if (!c.is_number()) bad("coordinates must be numbers");
      const Vec3 p{q[0].get<double>(), q[1].get<double>(), q.size() == 3 ? q[2].get<double>() : 0.0};
      double r = 0;
      if (has_r) {
        if (!l["radii"][k].is_number()) bad("radii must be numbers");
        r = l["radii"][k].get<double>();
      }
      check_vertex(p, r, "'" + name + "'");
      set.add(p, r);
    }
    set.end_line();
  }
  return set;
}

void write_polylines(const PolylineSet& set, const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".csv") write_file_atomically(path, encode_polylines_csv(set));
  else if (ext == ".json") write_file_atomically(path, encode_polylines_json(set));
  else invalid("'" + path + "': unsupported polyline format (use .csv or .json)");
}

PolylineSet read_polylines(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".csv") return decode_polylines_csv(read_file(path), path);
  if (ext == ".json") return decode_polylines_json(read_file(path), path);
  fail(FT_ERR_FORMAT, "'" + path + "': unsupported polyline format (use .csv or .json)");
}

}  // namespace ft::io
