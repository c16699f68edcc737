// The parameter tables through the ABI (fracterra/params.h).
#include "capi/guard.hpp"
#include "fracterra/fracterra.h"
#include "terrain/terrain_params.hpp"

using ft::capi::guarded;

namespace {

const ft::ParamTable& table_of(int32_t kind) {
  switch (kind) {
    case FT_PARAMS_TERRAIN: return ft::terrain_param_table();
    default:
      ft::invalid("params kind must be in 0.." + std::to_string(FT_PARAMS_KIND_COUNT - 1) + ", got " +
                  std::to_string(kind));
  }
}

}  // namespace

extern "C" {

FT_API ft_status ft_params_describe(int32_t kind, const char** struct_name, uint32_t* struct_size,
                                    int32_t* field_count) {
  return guarded([&] {
    const ft::ParamTable& t = table_of(kind);
    if (struct_name) *struct_name = t.struct_name;
    if (struct_size) *struct_size = uint32_t(t.struct_size);
    if (field_count) *field_count = int32_t(t.rows.size());
  });
}

FT_API ft_status ft_params_field(int32_t kind, int32_t index, const ft_param_info** out) {
  return guarded([&] {
    ft::capi::reset_out(out);
    const ft::ParamTable& t = table_of(kind);
    ft::check_int_range("index", index, 0, int64_t(t.rows.size()) - 1);
    *out = &t.rows[size_t(index)];
  });
}

}  // extern "C"
