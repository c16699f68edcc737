// SPDX-License-Identifier: GPL-3.0-or-later
// Stands in for exr.cpp in a build without OpenEXR (FT_WITH_OPENEXR=OFF: the
// Windows build): each call refuses with the library's name and the formats
// this build has.
#include "core/build_features.hpp"
#include "io/exr.hpp"

namespace ft::io {

void write_exr(const Heightfield&, const std::string& path, const char*) {
  needs("writing '" + path + "' as OpenEXR", "OpenEXR");
}
Heightfield read_exr(const std::string& path) { needs("reading '" + path + "' as OpenEXR", "OpenEXR"); }
Heightfield decode_exr(const std::string&) { needs("reading OpenEXR", "OpenEXR"); }

}  // namespace ft::io
