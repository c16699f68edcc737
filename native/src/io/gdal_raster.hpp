// SPDX-License-Identifier: GPL-3.0-or-later
// Rasters through GDAL: any raster GDAL reads (GeoTIFF, SRTM .hgt, ESRI
// ASCII grid, VRT, ...) as a heightfield, and heightfields written as
// Cloud-Optimized GeoTIFF. Band 1 is read as float32; the geotransform and
// CRS travel with the heightfield (Heightfield::georef) so that what is
// written from it is georeferenced too.
//
// World size: (width - 1) x the pixel width, the extent spanned by the sample
// centres (a mesh puts one vertex per sample). A geographic CRS has pixels in
// degrees: their width is turned into metres on the CRS's ellipsoid at the
// raster's centre latitude, as heights are in metres.
//
// Nodata (the band's nodata value, and NaN): refused with the count, filled
// by GDAL's GDALFillNodata (inverse-distance weighting of the nearest valid
// samples found along rays from each hole, no smoothing; valid samples are
// never changed), or kept as NaN for a caller that works around it (the DEM
// refinement picks a window without nodata).
#pragma once

#include <string>

#include "core/heightfield.hpp"

namespace ft::io {

// How a refusal names a raster format: "GeoTIFF (.tif)", "'.hgt'".
inline std::string raster_format_name(const std::string& extension) {
  if (extension == ".tif" || extension == ".tiff") return "GeoTIFF (" + extension + ")";
  return extension.empty() ? std::string("a file without an extension") : "'" + extension + "'";
}

enum class NodataPolicy { refuse, fill, keep };

Heightfield read_gdal(const std::string& path, NodataPolicy nodata = NodataPolicy::refuse);
// The same from bytes in memory (through GDAL's /vsimem/); `extension`
// (".tif", ".asc", ...) helps GDAL pick the driver.
Heightfield decode_gdal(const std::string& bytes, const std::string& extension,
                        NodataPolicy nodata = NodataPolicy::refuse);
// Cloud-Optimized GeoTIFF, float32, deflate with the floating-point
// predictor, with overviews; georeferenced when `hf` is. The world size of a
// heightfield without georeference is kept in the GDAL metadata item
// FRACTERRA_WORLD_SIZE. Written atomically.
void write_cog(const Heightfield& hf, const std::string& path);

}  // namespace ft::io
