// SPDX-License-Identifier: GPL-3.0-or-later
// The table of ft_fractalize_params (fracterra/params.h).
#pragma once

#include "core/param_table.hpp"

namespace ft::subdiv {

const ParamTable& fractalize_param_table();

}  // namespace ft::subdiv
