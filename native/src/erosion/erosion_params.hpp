// The table of ft_erosion_params (fracterra/params.h): every field's
// default, range, unit and labels, for the C ABI's init and range checks,
// the ctypes binding's Structure and the Blender add-on's properties.
#pragma once

#include "core/param_table.hpp"
#include "erosion/erosion.hpp"
#include "fracterra/erosion.h"

namespace ft::erosion {

const ParamTable& erosion_param_table();

// Between the C struct and the configuration (fields the struct lacks keep
// their defaults).
ft_erosion_params to_c(const ErosionConfig& c);
ErosionConfig from_c(const ft_erosion_params& p);

}  // namespace ft::erosion
