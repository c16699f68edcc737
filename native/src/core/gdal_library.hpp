// SPDX-License-Identifier: GPL-3.0-or-later
// The system's GDAL, opened at run time: the library and the add-on carry
// none of GDAL's ~60 dependencies, and GDAL is needed only for GeoTIFF/COG,
// the other rasters GDAL reads, GeoJSON and GeoPackage, and tile-set
// mosaics (io/gdal_api.hpp binds its functions). Any GDAL 3.x serves: its C
// API only grows.
//
// Which file: $FRACTERRA_GDAL when set (a path or a library name; the only
// candidate, so an explicit choice never falls back silently), else
// libgdal.so.<the GDAL this library was built with>, then the other GDAL 3.x
// sonames, newest first. Opened once, on first use; never closed.
#pragma once

#include <string>

namespace ft {

// The opened library, or nullptr when none could be (or this build has no
// GDAL support at all: kHaveGdal false, the Windows build).
void* gdal_library();
// True when GDAL's functions can be called: a build with GDAL support that
// found a GDAL on this system.
bool have_gdal();
// Throws FT_ERR_UNSUPPORTED: "<what> needs GDAL, ..." with what was tried,
// the package that brings GDAL and the formats that work without it.
[[noreturn]] void needs_gdal(const std::string& what);

}  // namespace ft
