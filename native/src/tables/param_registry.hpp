// SPDX-License-Identifier: GPL-3.0-or-later
// Every described params struct by its FT_PARAMS_* kind: the one list that
// the C ABI (ft_params_describe) and the CLI (`fracterra params`) share. A
// layer of its own because it gathers the tables of every capability.
#pragma once

#include "core/param_table.hpp"

namespace ft::tables {

// The table of `kind` (FT_PARAMS_*); throws ft::Error for an unknown kind.
const ParamTable& param_table(int32_t kind);
// Whether this build has `kind`: the kinds are numbered across branches, and
// one may be missing until its branch is merged.
bool has_param_table(int32_t kind);

}  // namespace ft::tables
