// SPDX-License-Identifier: GPL-3.0-or-later
// The parameter tables through the ABI (fracterra/params.h).
#include "capi/guard.hpp"
#include "fracterra/fracterra.h"
#include "tables/param_registry.hpp"

using ft::capi::guarded;

extern "C" {

FT_API ft_status ft_params_describe(int32_t kind, const char** struct_name, uint32_t* struct_size,
                                    int32_t* field_count) {
  return guarded([&] {
    const ft::ParamTable& t = ft::tables::param_table(kind);
    if (struct_name) *struct_name = t.struct_name;
    if (struct_size) *struct_size = uint32_t(t.struct_size);
    if (field_count) *field_count = int32_t(t.rows.size());
  });
}

FT_API ft_status ft_params_field(int32_t kind, int32_t index, const ft_param_info** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    const ft::ParamTable& t = ft::tables::param_table(kind);
    ft::check_int_range("index", index, 0, int64_t(t.rows.size()) - 1);
    *out = &t.rows[size_t(index)];
  });
}

}  // extern "C"
