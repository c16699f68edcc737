// SPDX-License-Identifier: GPL-3.0-or-later
// Heightfields to and from files, chosen by extension:
//   .png  16-bit grayscale, normalised to 0..65535, real min/max in tEXt
//         ("fracterra:min", "fracterra:max");
//   .pgm  16-bit P5, range in a comment;
//   .npy  float32, exact; its world size in a sidecar "<file>.npy.json" (read back when present);
//   .tif / .tiff  Cloud-Optimized GeoTIFF float32, exact, georeferenced
//         when the heightfield is (gdal_raster.hpp);
//   .exr  OpenEXR float, exact (exr.hpp);
//   .raw / .r16  RAW16 little-endian with a sidecar JSON (raw16.hpp).
// Reading restores real units where the range was recorded; otherwise
// samples are in 0..1. Any other extension is read through GDAL (GeoTIFF,
// SRTM .hgt, ESRI ASCII grid .asc, VRT, ...), whose nodata is refused or
// filled as `nodata` says.
#pragma once

#include <string>

#include "core/heightfield.hpp"
#include "io/gdal_raster.hpp"
#include "io/png_image.hpp"

namespace ft::io {

void write_heightfield(const Heightfield& hf, const std::string& path);
Heightfield read_heightfield(const std::string& path, NodataPolicy nodata = NodataPolicy::refuse);
// The normalised 16-bit image of a heightfield (with the range recorded).
GrayImage heightfield_to_image(const Heightfield& hf);
Heightfield image_to_heightfield(const GrayImage& image);
// Bytes in memory, with the format given by extension (".png", ".pgm",
// ".npy", ".exr", ".raw" / ".r16" without sidecar, else through GDAL).
Heightfield decode_heightfield(const std::string& bytes, const std::string& extension);

// The extensions write_heightfield knows, for messages and help texts.
// What this build writes (the Windows build has no GDAL or OpenEXR: core/build_features.hpp).
#if FT_WITH_GDAL && FT_WITH_OPENEXR
inline constexpr const char* kHeightfieldWriteFormats = ".png, .pgm, .npy, .tif, .exr, .raw or .r16";
#elif FT_WITH_GDAL
inline constexpr const char* kHeightfieldWriteFormats = ".png, .pgm, .npy, .tif, .raw or .r16";
#elif FT_WITH_OPENEXR
inline constexpr const char* kHeightfieldWriteFormats = ".png, .pgm, .npy, .exr, .raw or .r16";
#else
inline constexpr const char* kHeightfieldWriteFormats = ".png, .pgm, .npy, .raw or .r16";
#endif
inline constexpr const char* kHeightfieldReadHelp =
    "heightfield .png, .pgm, .npy, .exr, .raw/.r16, or any raster GDAL reads (.tif, .hgt, .asc, ...)";

}  // namespace ft::io
