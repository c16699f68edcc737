// SPDX-License-Identifier: GPL-3.0-or-later
// What this build has: the optional libraries (GDAL, OpenEXR, OpenSubdiv;
// CMake's FT_WITH_* options, all on for Linux and off for Windows; GDAL is
// the system's, found at run time: core/gdal_library.hpp) and so the
// heightfield formats it reads and writes. The stand-ins for a missing
// library (*_unavailable.cpp) refuse through needs(), so every refusal names
// the library and what the build does have.
#pragma once

#include <string>

namespace ft {

// kHaveGdal: built with GDAL's headers, to call a GDAL found at run time (have_gdal()).
inline constexpr bool kHaveGdal = FT_WITH_GDAL;
inline constexpr bool kHaveOpenExr = FT_WITH_OPENEXR;
inline constexpr bool kHaveOpenSubdiv = FT_WITH_OPENSUBDIV;

// "gdal openexr opensubdiv", or the part of it this build has ("gdal" when
// the system's GDAL was found).
const char* build_features();
// "PNG, PGM, NPY, RAW16, GeoTIFF, OpenEXR and every raster GDAL reads", or
// the part of it this build has ("PNG, PGM, NPY and RAW16").
const char* heightfield_formats();
// Throws FT_ERR_UNSUPPORTED: "<what> needs <library>; this build (without
// it) reads and writes <heightfield_formats()>".
[[noreturn]] void needs(const std::string& what, const char* library);

}  // namespace ft
