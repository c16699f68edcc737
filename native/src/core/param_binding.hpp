// SPDX-License-Identifier: GPL-3.0-or-later
// A library's own settings type filled from a params struct through its
// table: one binding per row, naming the row and the member it sets. The
// struct's ranges are checked once (check_ranges), then every bound row is
// read as a number (read_number) and stored with the member's type, so a
// converter is a list of names instead of hand-written copies, and a test can
// ask which settings rows a converter leaves out (unbound_rows).
#pragma once

#include <array>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"
#include "core/param_table.hpp"

namespace ft {

template <class Config>
struct ParamBinding {
  const char* row;  // the table row, by its field name
  void (*store)(Config& config, const ft_param_info& row, const void* params);
};

namespace detail {

template <class T>
void store_number(T& member, const ft_param_info& row, const void* params, int element = 0) {
  const double v = read_number(row, params, element);
  if constexpr (std::is_enum_v<T>) member = T(std::underlying_type_t<T>(v));
  else if constexpr (std::is_same_v<T, bool>) member = v != 0;
  else member = T(v);
}

template <class T, size_t N>
void store_number(std::array<T, N>& member, const ft_param_info& row, const void* params) {
  if (size_t(row.count) != N) invalid(std::string("the binding of ") + row.name + " expects " + std::to_string(N) +
                                      " elements, the row has " + std::to_string(row.count));
  for (size_t k = 0; k < N; ++k) store_number(member[k], row, params, int(k));
}

}  // namespace detail

// FT_PARAM_BIND(Config, row, member): row `row` of the struct into
// `config.member` (a member path such as camera.azimuth_deg; an array row
// goes into a std::array of its length).
#define FT_PARAM_BIND(Config, row, member)                                                 \
  ::ft::ParamBinding<Config> {                                                             \
    #row, [](Config& config, const ft_param_info& info, const void* params) {             \
      ::ft::detail::store_number(config.member, info, params);                             \
    }                                                                                      \
  }

// Checks `params` against `table`, then stores every bound row into `config`.
template <class Config>
void apply_bindings(const ParamTable& table, const void* params, std::span<const ParamBinding<Config>> bindings,
                    Config& config) {
  check_ranges(table, params);
  for (const ParamBinding<Config>& b : bindings) {
    const ft_param_info* row = find_row(table, b.row);
    if (!row) invalid(std::string(table.struct_name) + " has no row " + b.row + " to bind");
    b.store(config, *row, params);
  }
}

// The table's settings rows (not struct_size, not data) no binding names.
template <class Config>
std::vector<std::string> unbound_rows(const ParamTable& table, std::span<const ParamBinding<Config>> bindings) {
  std::vector<std::string> out;
  for (const ft_param_info& row : table.rows) {
    if (row.flags & (FT_PARAM_FLAG_STRUCT_SIZE | FT_PARAM_FLAG_DATA)) continue;
    bool bound = false;
    for (const ParamBinding<Config>& b : bindings) bound = bound || std::string(b.row) == row.name;
    if (!bound) out.push_back(row.name);
  }
  return out;
}

}  // namespace ft
