// SPDX-License-Identifier: GPL-3.0-or-later
// Reading any GDAL raster as a heightfield (see gdal_raster.hpp).

#include <cmath>
#include <memory>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "io/atomic_file.hpp"
#include "io/gdal_raster.hpp"
#include "io/gdal_session.hpp"

namespace ft::io {
namespace {

// Pixel width in metres for a geographic CRS (degrees), else as given.
double pixel_width_in_metres(const GeoReference& g, int32_t height) {
  const double dx = std::hypot(g.transform[1], g.transform[4]);
  if (g.crs_wkt.empty()) return dx;
  OGRSpatialReferenceH srs = gdal().OSRNewSpatialReference(g.crs_wkt.c_str());
  if (srs == nullptr) return dx;
  double scale = 1.0;
  if (gdal().OSRIsGeographic(srs)) {
    OGRErr err = OGRERR_NONE;
    const double a = gdal().OSRGetSemiMajor(srs, &err);
    const double lat = g.transform[3] + g.transform[5] * height * 0.5;
    const double kPi = 3.14159265358979323846;
    if (err == OGRERR_NONE && std::isfinite(lat) && std::abs(lat) < 90) scale = a * kPi / 180 * std::cos(lat * kPi / 180);
  } else {
    scale = gdal().OSRGetLinearUnits(srs, nullptr);  // metres per CRS unit
  }
  gdal().OSRDestroySpatialReference(srs);
  return dx * scale;
}

// How far (in samples) GDALFillNodata looks for valid samples from a hole.
// Its cost grows with the distance times the raster's samples (about 1-3 ns
// each on the project's machine): the raster's own side made a 9 x 65289
// GeoTIFF of nodata take minutes (a fuzz finding). Holes up to twice this
// across are filled; farther samples are refused with their count.
constexpr double kFillSearchDistance = 256;

// Fills NaN samples with GDALFillNodata on an in-memory copy of the band.
void fill_nodata(Heightfield& hf, const std::string& name, GdalSession& session) {
  GDALDriverH mem = gdal().GDALGetDriverByName("MEM");
  if (mem == nullptr) session.fail(FT_ERR_UNSUPPORTED, "GDAL's MEM driver is missing");
  GdalDataset ds(gdal().GDALCreate(mem, "", hf.width(), hf.height(), 1, GDT_Float32, nullptr));
  if (!ds) session.fail(FT_ERR_OUT_OF_MEMORY, "cannot make an in-memory copy to fill nodata");
  GDALRasterBandH band = gdal().GDALGetRasterBand(ds.get(), 1);
  gdal().GDALSetRasterNoDataValue(band, std::nan(""));
  if (gdal().GDALRasterIO(band, GF_Write, 0, 0, hf.width(), hf.height(), hf.data(), hf.width(), hf.height(), GDT_Float32, 0,
                   0) != CE_None)
    session.fail(FT_ERR_INTERNAL, "cannot copy the heightfield to fill its nodata");
  // Its work rasters in memory: by default GDAL writes them as GTiff files in
  // the current directory, which Blender's may not allow.
  char mem_work[] = "TEMP_FILE_DRIVER=MEM";
  char* options[] = {mem_work, nullptr};
  if (gdal().GDALFillNodata(band, nullptr, kFillSearchDistance, 0, 0, options, nullptr, nullptr) != CE_None ||
      gdal().GDALRasterIO(band, GF_Read, 0, 0, hf.width(), hf.height(), hf.data(), hf.width(), hf.height(), GDT_Float32, 0,
                   0) != CE_None)
    session.fail(FT_ERR_INTERNAL, "GDAL could not fill the nodata");
  size_t unfilled = 0;
  for (size_t i = 0; i < hf.size(); ++i) unfilled += std::isnan(hf.data()[i]) ? 1 : 0;
  if (unfilled > 0)
    fail(FT_ERR_FORMAT, "'" + name + "' has " + std::to_string(unfilled) + " nodata samples farther than " +
                            std::to_string(int(kFillSearchDistance)) +
                            " samples from any valid one, too far to fill (choose a window with smaller holes, or fill "
                            "them beforehand, e.g. with gdal_fillnodata.py)");
}

Heightfield read_dataset(GDALDatasetH ds, const std::string& name, NodataPolicy policy, GdalSession& session) {
  if (gdal().GDALGetRasterCount(ds) < 1) fail(FT_ERR_FORMAT, "'" + name + "' holds no raster band");
  const int w = gdal().GDALGetRasterXSize(ds), h = gdal().GDALGetRasterYSize(ds);
  if (w < 2 || h < 2)
    fail(FT_ERR_FORMAT, "'" + name + "' is " + std::to_string(w) + " x " + std::to_string(h) +
                            "; a heightfield needs at least 2 x 2 samples");
  // Checked against the memory cap (by the constructor) before anything is read.
  Heightfield hf(w, h);
  GDALRasterBandH band = gdal().GDALGetRasterBand(ds, 1);
  // Some drivers report a damaged block and still return CE_None: any failure
  // GDAL reported counts.
  if (gdal().GDALRasterIO(band, GF_Read, 0, 0, w, h, hf.data(), w, h, GDT_Float32, 0, 0) != CE_None ||
      !session.first_error().empty())
    session.fail(FT_ERR_FORMAT, "cannot read the samples of '" + name + "'");

  int has_nodata = 0;
  const double nodata = gdal().GDALGetRasterNoDataValue(band, &has_nodata);
  const float nodata_f = float(nodata);
  size_t missing = 0;
  float* z = hf.data();
  for (size_t i = 0; i < hf.size(); ++i) {
    if (has_nodata && (z[i] == nodata_f || (std::isnan(nodata) && std::isnan(z[i])))) z[i] = std::nanf("");
    if (!std::isfinite(z[i])) z[i] = std::nanf(""), ++missing;
  }
  if (missing == hf.size()) fail(FT_ERR_FORMAT, "'" + name + "' holds no valid sample (all are nodata)");
  if (missing > 0 && policy != NodataPolicy::keep) {
    if (policy == NodataPolicy::refuse)
      fail(FT_ERR_FORMAT, "'" + name + "' has " + std::to_string(missing) + " nodata samples of " +
                              std::to_string(hf.size()) + " (fill them with --nodata fill, or choose a window "
                              "without them)");
    fill_nodata(hf, name, session);
  }

  GeoReference g;
  if (const char* wkt = gdal().GDALGetProjectionRef(ds)) g.crs_wkt = wkt;
  g.has_transform = gdal().GDALGetGeoTransform(ds, g.transform.data()) == CE_None;
  // Our own files without a CRS say their world size exactly (their pixel
  // width is that size / (width - 1), rounded).
  const char* ws = g.crs_wkt.empty() ? gdal().GDALGetMetadataItem(ds, "FRACTERRA_WORLD_SIZE", nullptr) : nullptr;
  const double written = ws ? std::strtod(ws, nullptr) : NAN;
  if (std::isfinite(written) && written > 0) {
    hf.set_world_size(written);
  } else if (g.has_transform) {
    const double dx = pixel_width_in_metres(g, h);
    if (std::isfinite(dx) && dx > 0) hf.set_world_size(dx * (w - 1));
  }
  hf.set_georef(std::move(g));
  return hf;
}

}  // namespace

Heightfield read_gdal(const std::string& path, NodataPolicy nodata) {
  gdal("reading '" + path + "' as " + raster_format_name(extension_of(path)));
  GdalSession session;
  GdalDataset ds(gdal().GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds) {
    VSIStatBufL st;
    if (gdal().VSIStatL(path.c_str(), &st) != 0) fail(FT_ERR_IO, "cannot read '" + path + "': no such file");
    session.fail(FT_ERR_FORMAT, "'" + path + "' is not a raster GDAL can read");
  }
  return read_dataset(ds.get(), path, nodata, session);
}

Heightfield decode_gdal(const std::string& bytes, const std::string& extension, NodataPolicy nodata) {
  gdal("reading " + raster_format_name(extension));
  GdalSession session;
  GdalMemFile file(extension);
  const std::string& name = file.name();
  VSILFILE* f = gdal().VSIFileFromMemBuffer(name.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                                     vsi_l_offset(bytes.size()), FALSE);
  if (f == nullptr) session.fail(FT_ERR_INTERNAL, "cannot map the bytes for GDAL");
  gdal().VSIFCloseL(f);
  GdalDataset ds(gdal().GDALOpenEx(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds) session.fail(FT_ERR_FORMAT, "the bytes are not a raster GDAL can read");
  return read_dataset(ds.get(), "<memory>", nodata, session);
}

}  // namespace ft::io
