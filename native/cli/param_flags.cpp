// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli/param_flags.hpp"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>


namespace ft::cli {
namespace {

std::string lower_dashed(const char* s) {
  std::string out;
  for (; *s; ++s) out += *s == '_' || *s == ' ' ? '-' : char(std::tolower(static_cast<unsigned char>(*s)));
  return out;
}

std::string number_text(double v, bool integer) {
  if (integer) return std::to_string(static_cast<long long>(v));
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

bool is_integer(int32_t type) { return type != FT_PARAM_DOUBLE && type != FT_PARAM_FLOAT; }

std::string range_text(const ft_param_info& row) {
  if (row.flags & FT_PARAM_FLAG_ZERO_IS_AUTO) {
    ft_param_info plain = row;
    plain.flags &= ~uint32_t(FT_PARAM_FLAG_ZERO_IS_AUTO);
    return "auto (0) or " + range_text(plain);
  }
  const bool integer = is_integer(row.type);
  const bool lo = row.hard_min > -1.7e308, hi = row.hard_max < 1.7e308;
  const char* open = (row.flags & FT_PARAM_FLAG_MIN_EXCLUSIVE) ? "> " : ">= ";
  std::string unit = *row.unit ? std::string(" ") + row.unit : "";
  if (row.type == FT_PARAM_UINT64) return "";
  if (lo && hi) {
    if (integer) return number_text(row.hard_min, true) + ".." + number_text(row.hard_max, true) + unit;
    return std::string((row.flags & FT_PARAM_FLAG_MIN_EXCLUSIVE) ? "(" : "[") + number_text(row.hard_min, false) +
           ", " + number_text(row.hard_max, false) + ((row.flags & FT_PARAM_FLAG_MAX_EXCLUSIVE) ? ")" : "]") + unit;
  }
  if (lo) return open + number_text(row.hard_min, integer) + unit;
  if (hi) return "<= " + number_text(row.hard_max, integer) + unit;
  return unit.empty() ? "" : unit.substr(1);
}

// "fbm, interpolated: " when only some methods use the field.
std::string methods_text(const ParamTable& table, const ft_param_info& row) {
  const ft_param_info* method = find_row(table, "method");
  if (!method || row.methods == FT_PARAM_ALL_METHODS || &row == method) return "";
  std::string s;
  for (int i = 0; i < method->enum_count; ++i)
    if (row.methods & method_bit(method->enum_items[i].value)) s += (s.empty() ? "" : ", ") + cli_name(method->enum_items[i]);
  return s + ": ";
}

// A value the flag cannot hold is a parse error (CLI11's exit code and
// message); whether it is in range is the library's to say.
[[noreturn]] void bad(const std::string& message) { throw CLI::ValidationError(message); }

template <class T>
void store(void* params, const ft_param_info& row, T v) {
  std::memcpy(static_cast<char*>(params) + row.offset, &v, sizeof v);
}

// Parses `text` as the row's type and stores it; the ranges are the library's to check.
void parse_into(void* params, const ft_param_info& row, const std::string& text) {
  const std::string flag = flag_of(row.name);
  if (row.type == FT_PARAM_ENUM) {
    // By its name or by the label the add-on shows ("land" or "rugged-mountains").
    const std::string given = lower_dashed(text.c_str());
    auto label_name = [](const ft_param_enum_item& item) { return item.label ? lower_dashed(item.label) : ""; };
    for (int i = 0; i < row.enum_count; ++i)
      if (cli_name(row.enum_items[i]) == given || label_name(row.enum_items[i]) == given)
        return store(params, row, row.enum_items[i].value);
    std::string names;
    for (int i = 0; i < row.enum_count; ++i) {
      const std::string label = label_name(row.enum_items[i]);
      names += (i ? ", " : "") + cli_name(row.enum_items[i]) +
               (!label.empty() && label != cli_name(row.enum_items[i]) ? " (" + label + ")" : "");
    }
    bad(flag + " must be one of " + names + ", got '" + text + "'");
  }
  // "auto" is the sentinel the row documents (0).
  if ((row.flags & FT_PARAM_FLAG_ZERO_IS_AUTO) && lower_dashed(text.c_str()) == "auto") {
    std::memset(static_cast<char*>(params) + row.offset, 0, row.size);  // 0 of any numeric type
    return;
  }
  char* end = nullptr;
  errno = 0;
  const char* s = text.c_str();
  if (is_integer(row.type)) {
    const bool negative = text.find('-') != std::string::npos;
    if (row.type == FT_PARAM_UINT64 && negative) bad(flag + " must be a whole number >= 0, got '" + text + "'");
    const unsigned long long u = row.type == FT_PARAM_UINT64 ? std::strtoull(s, &end, 0) : 0;
    const long long v = row.type == FT_PARAM_UINT64 ? 0 : std::strtoll(s, &end, 10);
    if (end == s || *end || errno) bad(flag + " must be a whole number, got '" + text + "'");
    if (row.type == FT_PARAM_UINT64) return store(params, row, uint64_t(u));
    if (row.type == FT_PARAM_INT64) return store(params, row, int64_t(v));
    if (v < INT32_MIN || v > INT32_MAX) bad(flag + " is out of range, got '" + text + "'");
    return store(params, row, int32_t(v));
  }
  const double v = std::strtod(s, &end);
  if (end == s || *end) bad(flag + " must be a number, got '" + text + "'");
  if (row.type == FT_PARAM_FLOAT) return store(params, row, float(v));
  store(params, row, v);
}

std::string current_text(const void* params, const ft_param_info& row) {
  const double v = read_number(row, params);
  if (v == 0 && (row.flags & FT_PARAM_FLAG_ZERO_IS_AUTO)) return "auto";
  if (row.type == FT_PARAM_ENUM)
    for (int i = 0; i < row.enum_count; ++i)
      if (row.enum_items[i].value == int32_t(v)) return cli_name(row.enum_items[i]);
  if (row.type == FT_PARAM_UINT64) {
    uint64_t u;
    std::memcpy(&u, static_cast<const char*>(params) + row.offset, sizeof u);
    return std::to_string(u);
  }
  return number_text(v, is_integer(row.type));
}

}  // namespace

std::string flag_of(const char* field) { return "--" + lower_dashed(field); }

std::string cli_name(const ft_param_enum_item& item) { return lower_dashed(item.name); }

void add_param_flags(CLI::App& app, const ParamTable& table, void* params, const std::set<std::string>& skip,
                     const std::map<std::string, std::string>& aliases) {
  for (const ft_param_info& row : table.rows) {
    if ((row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) || skip.count(row.name) ||
        row.count != 1 || row.type == FT_PARAM_POINTER || row.type == FT_PARAM_STRING ||
        row.type == FT_PARAM_CALLBACK)
      continue;
    std::string help = methods_text(table, row) + row.label + ": " + row.doc;
    const auto alias = aliases.find(row.name);
    const std::string names = flag_of(row.name) + (alias == aliases.end() ? "" : "," + alias->second);
    if (row.type == FT_PARAM_BOOL) {
      const ft_param_info* r = &row;
      app.add_flag_callback(names, [params, r] { store(params, *r, int32_t(1)); },
                            help + (row.default_value != 0 ? " [default: on]" : ""));
      // A setting that is on by default needs a way to turn it off.
      if (row.default_value != 0)
        app.add_flag_callback("--no-" + flag_of(row.name).substr(2), [params, r] { store(params, *r, int32_t(0)); },
                              "turn " + flag_of(row.name) + " off");
      continue;
    }
    // An enum's values say what each one means: the table documents them one by one.
    if (row.type == FT_PARAM_ENUM)
      for (int i = 0; i < row.enum_count; ++i)
        help += std::string(i ? "; " : ". ") + cli_name(row.enum_items[i]) + ": " + row.enum_items[i].doc;
    const std::string range = row.type == FT_PARAM_ENUM ? "" : range_text(row);
    if (!range.empty()) help += "; range " + range;
    std::string type = row.type == FT_PARAM_ENUM ? "" : is_integer(row.type) ? (row.type == FT_PARAM_UINT64 ? "UINT" : "INT")
                                                                             : "FLOAT";
    if (row.type == FT_PARAM_ENUM) {
      for (int i = 0; i < row.enum_count; ++i) type += (i ? "|" : "") + cli_name(row.enum_items[i]);
    }
    const ft_param_info* r = &row;
    app.add_option_function<std::string>(names,
                                         [params, r](const std::string& text) { parse_into(params, *r, text); }, help)
        ->type_name(type)
        ->default_str(current_text(params, row));
  }
}

bool flag_given(const CLI::App& app, const char* field) {
  const std::string flag = flag_of(field);
  for (const std::string& name : {flag, "--no-" + flag.substr(2)})
    if (const CLI::Option* o = app.get_option_no_throw(name); o && o->count() > 0) return true;
  return false;
}

void overlay_given_flags(const CLI::App& app, const ParamTable& table, const void* given, void* base) {
  for (const ft_param_info& row : table.rows)
    if (!(row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) && flag_given(app, row.name))
      std::memcpy(static_cast<char*>(base) + row.offset, static_cast<const char*>(given) + row.offset, row.size);
}

}  // namespace ft::cli
