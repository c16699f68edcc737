// SPDX-License-Identifier: GPL-3.0-or-later
#include "splat/rules_json.hpp"

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "splat/splat_params.hpp"

namespace ft::splat {
namespace {

std::string field_list() {
  std::string s;
  for (const ft_param_info& row : splat_param_table().rows)
    if (!(row.flags & FT_PARAM_FLAG_STRUCT_SIZE)) s += (s.empty() ? "" : ", ") + std::string(row.name);
  return s;
}

double number_of(const nlohmann::json& v, const std::string& where) {
  if (!v.is_number()) invalid(where + " must be a number, got " + v.dump());
  return v.get<double>();
}

}  // namespace

SplatRules parse_rules(const std::string& text, const std::string& source) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    fail(FT_ERR_FORMAT, source + ": not JSON: " + e.what());
  }
  if (!j.is_object()) invalid(source + ": splat rules must be a JSON object {\"layers\": [...]}");
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "layers") invalid(source + ": unknown key '" + it.key() + "' (the rules hold only \"layers\")");
  if (!j.contains("layers") || !j["layers"].is_array() || j["layers"].empty())
    invalid(source + ": \"layers\" must be a non-empty array of layer objects");
  SplatRules r;
  const ParamTable& t = splat_param_table();
  int index = 0;
  for (const nlohmann::json& layer : j["layers"]) {
    const std::string at = source + ": layer " + std::to_string(index++);
    if (!layer.is_object()) invalid(at + " must be an object");
    ft_splat_params l = defaults_of<ft_splat_params>(t);
    if (!layer.contains("name") || !layer["name"].is_string() || layer["name"].get<std::string>().empty())
      invalid(at + " needs a \"name\" (a non-empty string)");
    r.names.push_back(layer["name"].get<std::string>());
    l.name = r.names.back().c_str();
    const std::string named = at + " ('" + r.names.back() + "')";
    for (auto it = layer.begin(); it != layer.end(); ++it) {
      if (it.key() == "name") continue;
      const ft_param_info* row = find_row(t, it.key().c_str());
      if (!row || (row->flags & FT_PARAM_FLAG_STRUCT_SIZE))
        invalid(named + ": unknown field '" + it.key() + "' (known: " + field_list() + ")");
      double* dst = reinterpret_cast<double*>(reinterpret_cast<char*>(&l) + row->offset);
      const std::string where = named + "." + it.key();
      if (row->count == 1) {
        dst[0] = number_of(it.value(), where);
      } else {
        if (!it.value().is_array() || int(it.value().size()) != row->count)
          invalid(where + " must be an array of " + std::to_string(row->count) + " numbers, got " +
                  it.value().dump());
        for (int e = 0; e < row->count; ++e) dst[e] = number_of(it.value()[size_t(e)], where);
      }
    }
    r.layers.push_back(l);
  }
  try {
    validate_layers(r.layers.data(), int32_t(r.layers.size()));
  } catch (const Error& e) {
    fail(e.status(), source + ": " + e.what());
  }
  return r;
}

SplatRules read_rules(const std::string& path) {
  std::ifstream f(platform::fs_path(path), std::ios::binary);
  if (!f) fail(FT_ERR_IO, "cannot open splat rules '" + path + "': " + std::strerror(errno));
  std::ostringstream s;
  s << f.rdbuf();
  return parse_rules(s.str(), path);
}

std::string rules_to_json(const std::vector<ft_splat_params>& layers) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  out["layers"] = nlohmann::ordered_json::array();
  for (const ft_splat_params& l : layers) {
    nlohmann::ordered_json o = nlohmann::ordered_json::object();
    o["name"] = l.name ? l.name : "";
    for (const ft_param_info& row : splat_param_table().rows) {
      if (row.type != FT_PARAM_DOUBLE) continue;
      const double* v = reinterpret_cast<const double*>(reinterpret_cast<const char*>(&l) + row.offset);
      if (row.count == 1) o[row.name] = v[0];
      else o[row.name] = std::vector<double>(v, v + row.count);
    }
    out["layers"].push_back(o);
  }
  return out.dump(2) + "\n";
}

}  // namespace ft::splat
