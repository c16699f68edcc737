// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/param_table.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "core/error.hpp"

namespace ft {
namespace {

template <class T>
T load(const void* p, size_t offset) {
  T v;
  std::memcpy(&v, static_cast<const char*>(p) + offset, sizeof v);
  return v;
}

template <class T>
void store(void* p, size_t offset, T v) {
  std::memcpy(static_cast<char*>(p) + offset, &v, sizeof v);
}

bool is_setting(const ft_param_info& row) {
  return !(row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) && row.type != FT_PARAM_POINTER &&
         row.type != FT_PARAM_STRING && row.type != FT_PARAM_CALLBACK;
}

std::string enum_choices(const ft_param_info& row) {
  std::string s;
  for (int i = 0; i < row.enum_count; ++i)
    s += (i ? ", " : "") + std::to_string(row.enum_items[i].value) + " (" + row.enum_items[i].name + ")";
  return s;
}

void check_enum(const ft_param_info& row, int32_t v) {
  for (int i = 0; i < row.enum_count; ++i)
    if (row.enum_items[i].value == v) return;
  invalid(std::string(row.name) + " must be one of " + enum_choices(row) + ", got " + std::to_string(v));
}

// The shortest of %.15g and %.17g that reads back as `v`: a range says 0.99,
// not 0.98999999999999999.
std::string short_number(double v) {
  if (!std::isfinite(v)) return format_number(v);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.15g", v);
  if (std::strtod(buf, nullptr) != v) return format_number(v);
  return buf;
}

std::string bound(double v) {
  return std::fabs(v) >= 1.7e308 ? (v < 0 ? "-inf" : "inf") : short_number(v);
}

void check_number(const ft_param_info& row, double v, bool integer) {
  if (v == 0 && (row.flags & FT_PARAM_FLAG_ZERO_IS_AUTO)) return;
  const bool lo_open = row.flags & FT_PARAM_FLAG_MIN_EXCLUSIVE, hi_open = row.flags & FT_PARAM_FLAG_MAX_EXCLUSIVE;
  const bool ok = std::isfinite(v) && (lo_open ? v > row.hard_min : v >= row.hard_min) &&
                  (hi_open ? v < row.hard_max : v <= row.hard_max);
  if (ok) return;
  const std::string name = row.name, value = integer ? std::to_string(int64_t(v)) : short_number(v);
  if (row.flags & FT_PARAM_FLAG_ZERO_IS_AUTO)
    invalid(name + " must be 0 (auto) or in " + (lo_open ? "(" : "[") + bound(row.hard_min) + ", " +
            bound(row.hard_max) + (hi_open ? ")" : "]") + ", got " + value);
  if (integer) invalid(name + " must be in " + bound(row.hard_min) + ".." + bound(row.hard_max) + ", got " + value);
  // The words of check_range / check_positive, which the messages had before the tables.
  if (row.hard_max >= 1.7e308 && row.hard_min <= -1.7e308) invalid(name + " must be a finite number, got " + value);
  if (row.hard_max >= 1.7e308)
    invalid(name + " must be a finite number " + (lo_open ? "> " : ">= ") + bound(row.hard_min) + ", got " + value);
  if (row.hard_min <= -1.7e308)
    invalid(name + " must be a finite number " + (hi_open ? "< " : "<= ") + bound(row.hard_max) + ", got " + value);
  invalid(name + " must be in " + (lo_open ? "(" : "[") + bound(row.hard_min) + ", " + bound(row.hard_max) +
          (hi_open ? ")" : "]") + ", got " + value);
}

}  // namespace

double read_number(const ft_param_info& row, const void* p, int element) {
  const size_t at = row.offset + size_t(element) * param_element_size(row.type);
  switch (row.type) {
    case FT_PARAM_UINT32: return load<uint32_t>(p, at);
    case FT_PARAM_INT32: case FT_PARAM_BOOL: case FT_PARAM_ENUM: return load<int32_t>(p, at);
    case FT_PARAM_INT64: return double(load<int64_t>(p, at));
    case FT_PARAM_UINT64: return double(load<uint64_t>(p, at));
    case FT_PARAM_FLOAT: return load<float>(p, at);
    case FT_PARAM_DOUBLE: return load<double>(p, at);
    default: return 0;
  }
}

const ft_param_info* find_row(const ParamTable& t, const char* name) {
  for (const auto& row : t.rows)
    if (std::strcmp(row.name, name) == 0) return &row;
  return nullptr;
}

void fill_defaults(const ParamTable& t, void* p) {
  std::memset(p, 0, t.struct_size);
  for (const auto& row : t.rows) {
    for (int e = 0; e < row.count; ++e) {
      const size_t at = row.offset + size_t(e) * param_element_size(row.type);
      const double d = row.default_value;
      switch (row.type) {
        case FT_PARAM_UINT32: store(p, at, uint32_t(d)); break;
        case FT_PARAM_INT32: case FT_PARAM_BOOL: case FT_PARAM_ENUM: store(p, at, int32_t(d)); break;
        case FT_PARAM_INT64: store(p, at, int64_t(d)); break;
        case FT_PARAM_UINT64: store(p, at, uint64_t(d)); break;
        case FT_PARAM_FLOAT: store(p, at, float(d)); break;
        case FT_PARAM_DOUBLE: store(p, at, d); break;
        default: break;  // pointers and callbacks: NULL
      }
    }
  }
  store(p, 0, uint32_t(t.struct_size));
}

void upgrade(const ParamTable& t, const void* in, void* out) {
  check_not_null(t.struct_name, in);
  const uint32_t given = load<uint32_t>(in, 0);
  // The sizes the struct has had: where each later version's fields begin.
  bool known = given == t.struct_size;
  std::string sizes;
  for (size_t i = 1; i < t.rows.size(); ++i)
    if (t.rows[i].since > t.rows[i - 1].since) {
      known = known || given == t.rows[i].offset;
      sizes += std::to_string(t.rows[i].offset) + ", ";
    }
  if (!known)
    invalid(std::string(t.struct_name) + ".struct_size is " + std::to_string(given) + ", expected " + sizes +
            std::to_string(t.struct_size) + " (this library's size; the others are older versions'): fill it with " +
            t.struct_name + "_init, or set it to sizeof(" + t.struct_name + ")");
  fill_defaults(t, out);
  std::memcpy(out, in, given);
  store(out, 0, uint32_t(t.struct_size));
}

void check_ranges(const ParamTable& t, const void* p) {
  uint64_t used = FT_PARAM_ALL_METHODS;
  if (const ft_param_info* method = find_row(t, "method")) {
    const int32_t m = int32_t(read_number(*method, p));
    check_enum(*method, m);
    used = method_bit(m);
  }
  for (const auto& row : t.rows) {
    if (!is_setting(row) || !(row.methods & used) || row.type == FT_PARAM_BOOL || row.type == FT_PARAM_UINT64)
      continue;
    for (int e = 0; e < row.count; ++e) {
      const double v = read_number(row, p, e);
      if (row.type == FT_PARAM_ENUM) check_enum(row, int32_t(v));
      else check_number(row, v, row.type != FT_PARAM_FLOAT && row.type != FT_PARAM_DOUBLE);
    }
  }
}

}  // namespace ft
