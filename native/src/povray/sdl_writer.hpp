// SPDX-License-Identifier: GPL-3.0-or-later
// Small, safe pieces of POV-Ray scene description language (SDL): numbers
// that keep their shape, quoted strings that cannot break out of their
// quotes, checked identifiers, relative paths, and the fracterra -> POV-Ray
// axis mapping. Everything the povray layer writes goes through these.
#pragma once

#include <string>

#include "core/polyline_set.hpp"

namespace ft::pov {

// fracterra worlds are right-handed with z up; POV-Ray is left-handed with
// y up. Swapping y and z maps one onto the other and keeps the top view:
// world (x, y, z) -> POV <x, z, y>.
inline Vec3 to_pov(const Vec3& w) { return {w[0], w[2], w[1]}; }

// A finite number with 9 significant digits ("%.9g": float32 survives a
// round trip; Blender's exporter writes 4 and loses the shape of fine
// polylines). Throws FT_ERR_INVALID_ARGUMENT for NaN or infinity.
std::string number(double v);
// "<x, y, z>" of a POV-Ray vector (already in POV axes).
std::string vec(const Vec3& v);
// A double-quoted SDL string literal (file names). Quotes are escaped so no
// text can end the literal early; backslashes (POV-Ray keeps "\\" as two)
// and control characters are refused: a scene path never needs them.
std::string quoted(const std::string& text);
// `name` when it is a safe SDL identifier of ours: letters, digits and '_',
// starting with a letter, at most 40 characters, with at least one capital
// letter (POV-Ray's keywords are all lower case, so it cannot clash).
const std::string& identifier(const std::string& name, const char* what);
// One line of text safe inside a `//` comment (line breaks become spaces).
std::string comment_text(const std::string& text);
// `target` relative to folder `from_dir`, with '/' separators: scenes refer
// to their images relatively so a scene folder can be moved as a whole.
std::string relative_path(const std::string& target, const std::string& from_dir);
// The folder of a file path ("." for a bare name).
std::string folder_of(const std::string& path);

}  // namespace ft::pov
