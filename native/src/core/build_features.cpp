// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/build_features.hpp"

#include "core/error.hpp"
#include "core/gdal_library.hpp"

namespace ft {

const char* build_features() {
  static const std::string s = [] {
    std::string out;
    for (auto [have, name] : {std::pair{have_gdal(), "gdal"}, {kHaveOpenExr, "openexr"}, {kHaveOpenSubdiv, "opensubdiv"}})
      if (have) out += (out.empty() ? "" : " ") + std::string(name);
    return out;
  }();
  return s.c_str();
}

const char* heightfield_formats() {
  const bool gdal = have_gdal();
  if (gdal && kHaveOpenExr) return "PNG, PGM, NPY, RAW16, GeoTIFF, OpenEXR and every raster GDAL reads";
  if (gdal) return "PNG, PGM, NPY, RAW16, GeoTIFF and every raster GDAL reads";
  if (kHaveOpenExr) return "PNG, PGM, NPY, RAW16 and OpenEXR";
  return "PNG, PGM, NPY and RAW16";
}

void needs(const std::string& what, const char* library) {
  fail(FT_ERR_UNSUPPORTED, what + " needs " + library + ", and this build of fracterra has none (" +
                               "the Windows build goes without it, docs/windows.md); it reads and writes " +
                               heightfield_formats());
}

}  // namespace ft
