// SPDX-License-Identifier: GPL-3.0-or-later
// Stands in for gdal_reader.cpp, gdal_writer.cpp and vector_writer.cpp in a
// build without GDAL (FT_WITH_GDAL=OFF: the Windows build): each refuses
// with the library's name and the formats this build has.
#include "core/build_features.hpp"
#include "io/atomic_file.hpp"
#include "io/gdal_raster.hpp"
#include "io/vector_io.hpp"

namespace ft::io {
Heightfield read_gdal(const std::string& path, NodataPolicy) {
  needs("reading '" + path + "' as " + raster_format_name(extension_of(path)), "GDAL");
}

Heightfield decode_gdal(const std::string&, const std::string& extension, NodataPolicy) {
  needs("reading " + raster_format_name(extension), "GDAL");
}

void write_cog(const Heightfield&, const std::string& path) {
  needs("writing '" + path + "' as GeoTIFF", "GDAL");
}

void write_vector_layers(const std::vector<VectorLayer>&, const GeoReference&, double, const std::string& path) {
  needs("writing '" + path + "' (GeoJSON or GeoPackage; .csv and .json need nothing)", "GDAL");
}

}  // namespace ft::io
