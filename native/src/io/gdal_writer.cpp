// SPDX-License-Identifier: GPL-3.0-or-later
// Heightfields as Cloud-Optimized GeoTIFF (see gdal_raster.hpp). GDAL's COG
// driver writes into /vsimem/ and the finished bytes go to disk through
// write_file_atomically, so a failure never leaves a partial file.

#include <array>
#include <cmath>
#include <memory>
#include <string_view>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/gdal_raster.hpp"
#include "io/gdal_session.hpp"

namespace ft::io {
namespace {

struct Options {
  char** list = nullptr;
  ~Options() { gdal().CSLDestroy(list); }
  void set(const char* key, const char* value) { list = gdal().CSLSetNameValue(list, key, value); }
};

}  // namespace

void write_cog(const Heightfield& hf, const std::string& path) {
  const HeightStats s = hf.stats();
  if (!std::isfinite(s.min) || !std::isfinite(s.max)) invalid("the heightfield holds NaN or infinite samples");
  gdal("writing '" + path + "' as GeoTIFF");
  GdalSession session;
  GDALDriverH mem = gdal().GDALGetDriverByName("MEM"), cog = gdal().GDALGetDriverByName("COG");
  if (mem == nullptr || cog == nullptr) fail(FT_ERR_UNSUPPORTED, "this GDAL has no MEM or COG driver (GDAL >= 3.1)");
  // An in-memory copy is the source (GDAL 3.10 and later refuse to open
  // "MEM:::DATAPOINTER" names, which would have avoided the copy).
  check_allocation(checked_bytes(hf.size(), sizeof(float)), "the GeoTIFF's in-memory copy of the heightfield");
  GdalDataset src(gdal().GDALCreate(mem, "", hf.width(), hf.height(), 1, GDT_Float32, nullptr));
  if (!src) session.fail(FT_ERR_OUT_OF_MEMORY, "cannot make the in-memory copy for GDAL");
  if (gdal().GDALRasterIO(gdal().GDALGetRasterBand(src.get(), 1), GF_Write, 0, 0, hf.width(), hf.height(),
                   const_cast<float*>(hf.data()), hf.width(), hf.height(), GDT_Float32, 0, 0) != CE_None)
    session.fail(FT_ERR_INTERNAL, "cannot copy the heightfield for GDAL");
  const GeoReference& g = hf.georef();
  if (g.has_transform) {
    gdal().GDALSetGeoTransform(src.get(), const_cast<double*>(g.transform.data()));
  } else if (hf.world_size() > 0 && hf.width() > 1) {
    // North up, sample (0, 0) centred on the origin: a tile set's frame
    // (tile_geotransform), so the whole and its tiles overlay in a GIS.
    const double s = hf.world_size() / (hf.width() - 1);
    std::array<double, 6> t = {-0.5 * s, s, 0.0, 0.5 * s, 0.0, -s};
    gdal().GDALSetGeoTransform(src.get(), t.data());
  }
  if (!g.crs_wkt.empty()) gdal().GDALSetProjection(src.get(), g.crs_wkt.c_str());
  if (g.crs_wkt.empty() && hf.world_size() > 0)
    gdal().GDALSetMetadataItem(src.get(), "FRACTERRA_WORLD_SIZE", format_number(hf.world_size()).c_str(), nullptr);
  gdal().GDALSetMetadataItem(src.get(), "TIFFTAG_SOFTWARE", "fracterra", nullptr);

  Options o;
  o.set("COMPRESS", "DEFLATE");
  // Level 1 of libdeflate: 4097^2 float32 with its overviews in 1.5 s of CPU
  // against 2.5 s at GDAL's default 6, for a file 2.4 % larger (a tile set's
  // six maps a tile are most of its writing: docs/measurements/scale.md).
  // Any DEFLATE reader reads it; ZSTD, faster still, is not in every GIS.
  o.set("LEVEL", "1");
  o.set("PREDICTOR", "YES");  // floating-point predictor for float32
  o.set("OVERVIEWS", "AUTO");
  o.set("RESAMPLING", "AVERAGE");
  GdalMemFile file(".tif");
  const std::string& name = file.name();
  {
    GdalDataset out(gdal().GDALCreateCopy(cog, name.c_str(), src.get(), FALSE, o.list, nullptr, nullptr));
    if (!out) session.fail(FT_ERR_IO, "GDAL could not write the GeoTIFF '" + path + "'");
  }
  vsi_l_offset length = 0;
  GByte* bytes = gdal().VSIGetMemFileBuffer(name.c_str(), &length, FALSE);
  if (bytes == nullptr || !session.first_error().empty())
    session.fail(FT_ERR_IO, "GDAL could not write the GeoTIFF '" + path + "'");
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(bytes), size_t(length)));
}

}  // namespace ft::io
