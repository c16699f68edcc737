// SPDX-License-Identifier: GPL-3.0-or-later
// fracterra params: the library's parameter tables (fracterra/params.h), as
// text or as JSON for other tools (and for the test that C, CLI, Python and
// Blender agree).
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/command.hpp"
#include "cli/param_flags.hpp"
#include "io/atomic_file.hpp"
#include "tables/param_registry.hpp"

namespace ft::cli::cmd_params {
namespace {

const char* type_name(int32_t type) {
  static const char* const names[] = {"uint32", "int32",  "int64",  "uint64",   "float",  "double",
                                      "bool",   "enum",   "pointer", "string", "callback", "opaque"};
  return type >= 0 && type < int32_t(std::size(names)) ? names[type] : "unknown";
}

// JSON has no infinity: an unbounded side is null.
nlohmann::json bound(double v) { return std::fabs(v) >= 1.7e308 ? nlohmann::json() : nlohmann::json(v); }

nlohmann::json row_json(const ft_param_info& row) {
  nlohmann::json j = {{"name", row.name},
                      {"flag", row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA) ? nlohmann::json()
                                                                                             : nlohmann::json(flag_of(row.name))},
                      {"type", type_name(row.type)},
                      {"offset", row.offset},
                      {"size", row.size},
                      {"count", row.count},
                      {"flags", row.flags},
                      {"since", row.since},
                      {"default", row.default_value},
                      {"hard_min", bound(row.hard_min)},
                      {"hard_max", bound(row.hard_max)},
                      {"min_exclusive", (row.flags & FT_PARAM_FLAG_MIN_EXCLUSIVE) != 0},
                      {"max_exclusive", (row.flags & FT_PARAM_FLAG_MAX_EXCLUSIVE) != 0},
                      {"soft_min", bound(row.soft_min)},
                      {"soft_max", bound(row.soft_max)},
                      {"unit", row.unit},
                      {"label", row.label},
                      {"doc", row.doc},
                      {"methods", row.methods}};
  if (row.type == FT_PARAM_POINTER) j["element_type"] = type_name(row.element_type), j["element_kind"] = row.element_kind;
  nlohmann::json items = nlohmann::json::array();
  for (int i = 0; i < row.enum_count; ++i) {
    const ft_param_enum_item& e = row.enum_items[i];
    items.push_back({{"value", e.value}, {"name", e.name}, {"cli", cli_name(e)}, {"label", e.label}, {"doc", e.doc}});
  }
  if (row.type == FT_PARAM_ENUM) j["items"] = items;
  return j;
}

int run(bool json, const std::string& out) {
  nlohmann::json all = nlohmann::json::object();
  for (int32_t kind = 0; kind < FT_PARAMS_KIND_COUNT; ++kind) {
    if (!tables::has_param_table(kind)) continue;  // a kind number given to a branch not merged here
    const ParamTable& t = tables::param_table(kind);
    if (!json) {
      std::printf("%s (%zu bytes)\n", t.struct_name, t.struct_size);
      for (const ft_param_info& row : t.rows)
        std::printf("  %-22s %-8s default %-10g %s\n", row.name, type_name(row.type), row.default_value, row.label);
      continue;
    }
    nlohmann::json fields = nlohmann::json::array();
    for (const ft_param_info& row : t.rows) fields.push_back(row_json(row));
    all[t.struct_name] = {{"kind", kind}, {"size", t.struct_size}, {"fields", fields}};
  }
  if (!json) return 0;
  if (out.empty()) std::printf("%s\n", all.dump(1).c_str());
  else io::write_file_atomically(out, all.dump(1) + "\n");
  return 0;
}

Registration reg({"params", "List the library's parameter tables: every field's default, range, unit and meaning",
                  [](CLI::App& app) -> std::function<int()> {
                    auto json = std::make_shared<bool>(false);
                    auto out = std::make_shared<std::string>();
                    app.add_flag("--json", *json, "print them as JSON (the form tools read)");
                    app.add_option("--out", *out, "with --json: write the JSON to this file instead");
                    return [json, out] { return run(*json, *out); };
                  },
                  95});

}  // namespace
}  // namespace ft::cli::cmd_params
