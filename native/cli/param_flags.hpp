// SPDX-License-Identifier: GPL-3.0-or-later
// A params struct's flags, built from its table (fracterra/params.h): one
// flag per setting, named after the field (`octave_rotation` is
// --octave-rotation), with the table's label, documentation, range, unit,
// default and the methods that use it in --help. A subcommand calls
// add_param_flags instead of writing its flags by hand, so the CLI cannot
// disagree with the library about a name, a default or a range; the library
// validates the values (one message for C, Python and the CLI).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <set>
#include <string>

#include "core/param_table.hpp"

namespace ft::cli {

// "--octave-rotation" for octave_rotation.
std::string flag_of(const char* field);
// An enum item's CLI name: "cellular-f2f1" for CELLULAR_F2F1.
std::string cli_name(const ft_param_enum_item& item);

// Adds a flag for every row of `table` that is a setting (not struct_size, not
// data such as pointers, counts or callbacks), except the fields in `skip`
// (a subcommand may offer its own form, e.g. --size WxH for width and
// height). The flags write into `params`, a struct of the table's type that
// must outlive parsing and be filled with its defaults beforehand (its values
// are the defaults --help shows). `aliases` gives a field further flag names
// that users relied on before the flags came from the table (e.g. "--points"
// for ifs_points), as CLI11 names: "--points" or "--a,--b". Returns nothing:
// errors are the library's.
void add_param_flags(CLI::App& app, const ParamTable& table, void* params, const std::set<std::string>& skip = {},
                     const std::map<std::string, std::string>& aliases = {});

// Whether the flag of field `field` (under any of its names, or its --no-X
// form) was given on the command line.
bool flag_given(const CLI::App& app, const char* field);

// Copies from `given` (the struct add_param_flags wrote into) over `base`
// (a struct of the same table, e.g. a preset's) the fields whose flags were
// given on the command line: a preset under explicit flags.
void overlay_given_flags(const CLI::App& app, const ParamTable& table, const void* given, void* base);

}  // namespace ft::cli
