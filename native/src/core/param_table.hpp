// SPDX-License-Identifier: GPL-3.0-or-later
// A params struct's table: one row per field (fracterra/params.h). From it
// come the defaults that ft_*_params_init writes, the range checks every
// method shares, and the upgrading of a struct from an older caller. Only
// the checks that relate several fields stay in each method's validator.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "fracterra/params.h"

namespace ft {

struct ParamTable {
  const char* struct_name;            // "ft_terrain_params"
  size_t struct_size;                 // sizeof the struct in this library
  std::span<const ft_param_info> rows;  // in offset order; rows[0] is struct_size
};

// Rows name only the members they need: the others are zero by design (no
// flags, first version, no enum), so GCC's -Wextra note about omitted
// designated initializers says nothing here. Table files put
// FT_PARAM_TABLE_BEGIN / FT_PARAM_TABLE_END around their rows.
#define FT_PARAM_TABLE_BEGIN \
  _Pragma("GCC diagnostic push") _Pragma("GCC diagnostic ignored \"-Wmissing-field-initializers\"")
#define FT_PARAM_TABLE_END _Pragma("GCC diagnostic pop")

// A row's start: name, type, offset and size from the struct itself, so a
// row cannot point at the wrong bytes. Rows are written as
//   {FT_PARAM_ROW(ft_terrain_params, hurst, FT_PARAM_DOUBLE), .default_value = 0.8, ...}
#define FT_PARAM_ROW(Struct, field, param_type)                                                   \
  .struct_size = sizeof(ft_param_info), .type = (param_type), .name = #field,                    \
  .offset = uint32_t(offsetof(Struct, field)), .size = uint32_t(sizeof(Struct::field)),           \
  .count = int32_t(sizeof(Struct::field) / ::ft::param_element_size(param_type))

constexpr size_t param_element_size(int32_t type) {
  switch (type) {
    case FT_PARAM_INT64: case FT_PARAM_UINT64: case FT_PARAM_DOUBLE: return 8;
    case FT_PARAM_POINTER: case FT_PARAM_STRING: case FT_PARAM_CALLBACK: return sizeof(void*);
    default: return 4;
  }
}

// Bit m of a row's `methods`.
constexpr uint64_t method_bit(int m) { return uint64_t(1) << m; }

// The rows of the fields every long call's struct shares, the same bytes in
// each table: `threads`, the `progress` callback (its doc may say when it is
// called) and `progress_user`.
FT_PARAM_TABLE_BEGIN
template <class Struct>
constexpr ft_param_info threads_row() {
  return {FT_PARAM_ROW(Struct, threads, FT_PARAM_INT32), .element_kind = -1, .default_value = 0, .hard_min = 0,
          .hard_max = 1024, .soft_min = 0, .soft_max = 64, .unit = "threads", .label = "Threads",
          .doc = "Worker threads, 0: all cores; the output never depends on it", .methods = FT_PARAM_ALL_METHODS};
}
template <class Struct>
constexpr ft_param_info progress_row(const char* doc = "Progress callback; may cancel; NULL: none") {
  return {FT_PARAM_ROW(Struct, progress, FT_PARAM_CALLBACK), .flags = FT_PARAM_FLAG_DATA, .element_kind = -1,
          .unit = "", .label = "Progress", .doc = doc, .methods = FT_PARAM_ALL_METHODS};
}
template <class Struct>
constexpr ft_param_info progress_user_row() {
  return {FT_PARAM_ROW(Struct, progress_user, FT_PARAM_POINTER), .flags = FT_PARAM_FLAG_DATA,
          .element_type = FT_PARAM_OPAQUE, .element_kind = -1, .unit = "", .label = "Progress Data",
          .doc = "Passed to the progress callback", .methods = FT_PARAM_ALL_METHODS};
}
// A shared row in a table whose struct came with ABI minor `abi` (0x2000F: 2.15).
constexpr ft_param_info since(uint32_t abi, ft_param_info row) {
  row.since = abi;
  return row;
}
FT_PARAM_TABLE_END

const ft_param_info* find_row(const ParamTable& t, const char* name);

// Writes every row's default into `p` (and struct_size).
void fill_defaults(const ParamTable& t, void* p);

// `in` is a struct from a caller of this or an older ABI: its struct_size is
// this library's size or one the struct had in an earlier version (the offset
// of the first field added later). Copies the caller's bytes over the defaults
// into `out` (this library's size); throws naming the struct otherwise.
void upgrade(const ParamTable& t, const void* in, void* out);

// The hard ranges and enum values of the fields that the struct's method
// uses (every field when it has no `method`). Throws ft::Error naming the
// field, its value and what is allowed.
void check_ranges(const ParamTable& t, const void* p);

// Reads a numeric field as a double (enums, bools and integers too).
double read_number(const ft_param_info& row, const void* p, int element = 0);

// The caller's struct over the defaults, at this library's size (see upgrade()).
template <class T>
T upgraded(const ParamTable& t, const T& given) {
  T p;
  upgrade(t, &given, &p);
  return p;
}

template <class T>
T defaults_of(const ParamTable& t) {
  T p{};
  fill_defaults(t, &p);
  return p;
}

}  // namespace ft
