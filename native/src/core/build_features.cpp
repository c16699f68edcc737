#include "core/build_features.hpp"

#include "core/error.hpp"

namespace ft {

const char* build_features() {
  static const std::string s = [] {
    std::string out;
    for (auto [have, name] : {std::pair{kHaveGdal, "gdal"}, {kHaveOpenExr, "openexr"}, {kHaveOpenSubdiv, "opensubdiv"}})
      if (have) out += (out.empty() ? "" : " ") + std::string(name);
    return out;
  }();
  return s.c_str();
}

const char* heightfield_formats() {
  if (kHaveGdal && kHaveOpenExr) return "PNG, PGM, NPY, RAW16, GeoTIFF, OpenEXR and every raster GDAL reads";
  if (kHaveGdal) return "PNG, PGM, NPY, RAW16, GeoTIFF and every raster GDAL reads";
  if (kHaveOpenExr) return "PNG, PGM, NPY, RAW16 and OpenEXR";
  return "PNG, PGM, NPY and RAW16";
}

void needs(const std::string& what, const char* library) {
  fail(FT_ERR_UNSUPPORTED, what + " needs " + library + ", and this build of fracterra has none (" +
                               "the Windows build goes without it, docs/windows.md); it reads and writes " +
                               heightfield_formats());
}

}  // namespace ft
