// SPDX-License-Identifier: GPL-3.0-or-later
#include "tiles/mosaic_vrt.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "core/error.hpp"
#include "core/platform.hpp"
#include "io/gdal_session.hpp"

namespace ft::tiles {
namespace {

struct StringList {
  char** list = nullptr;
  ~StringList() { io::gdal().CSLDestroy(list); }
  void add(const std::string& s) { list = io::gdal().CSLAddString(list, s.c_str()); }
};

// GDAL's configuration options are process-wide: set for the overview build, then restored.
struct ConfigOption {
  std::string key, old;
  bool had = false;
  ConfigOption(const char* k, const char* value) : key(k) {
    if (const char* v = io::gdal().CPLGetConfigOption(k, nullptr)) old = v, had = true;
    io::gdal().CPLSetConfigOption(k, value);
  }
  ~ConfigOption() { io::gdal().CPLSetConfigOption(key.c_str(), had ? old.c_str() : nullptr); }
};

}  // namespace

namespace {

// A VRT of `files` (relative to `dir`) at `final_vrt` (relative), with its
// overviews in .ovr when `overviews`; temporary names, then renamed.
void build_vrt(const TileSpec& spec, const std::string& dir, const std::vector<std::string>& files,
               const std::string& final_name, bool scaled, bool overviews) {
  namespace fs = std::filesystem;
  const std::string final_vrt = platform::join_path(dir, final_name);
  const fs::path final_path = platform::fs_path(final_vrt);
  const std::string temp_vrt =
      platform::utf8_of(final_path.parent_path() / ("." + platform::utf8_of(final_path.stem()) + ".tmp.vrt"));
  fs::remove(platform::fs_path(temp_vrt));
  fs::remove(platform::fs_path(temp_vrt + ".ovr"));

  io::GdalSession session;
  StringList sources;
  for (const std::string& f : files) sources.add(platform::join_path(dir, f));
  {
    GDALBuildVRTOptions* options = io::gdal().GDALBuildVRTOptionsNew(nullptr, nullptr);
    int usage_error = 0;
    io::GdalDataset vrt(io::gdal().GDALBuildVRT(temp_vrt.c_str(), io::gdal().CSLCount(sources.list), nullptr, sources.list, options, &usage_error));
    io::gdal().GDALBuildVRTOptionsFree(options);
    if (!vrt) session.fail(FT_ERR_IO, "GDAL could not build the mosaic '" + final_vrt + "'");
    GDALRasterBandH band = io::gdal().GDALGetRasterBand(vrt.get(), 1);
    if (scaled) {
      io::gdal().GDALSetRasterOffset(band, spec.height_min);
      io::gdal().GDALSetRasterScale(band, (spec.height_max - spec.height_min) / 65535.0);
    }
    io::gdal().GDALSetMetadataItem(vrt.get(), "FRACTERRA_WORLD_SIZE",
                        format_number(spec.spacing * double(spec.grid.width - 1)).c_str(), nullptr);
  }
  // Overviews of the closed VRT go to its external .ovr (DEFLATE). GDAL
  // computes and compresses them on all cores unless GDAL_NUM_THREADS says
  // otherwise (the bytes do not depend on it); one thread took half of a
  // 65537^2 set's wall time.
  std::vector<int> factors;
  for (int f = 2; overviews && std::max(spec.grid.width, spec.grid.height) / f >= 256; f *= 2) factors.push_back(f);
  if (!factors.empty()) {
    ConfigOption compress("COMPRESS_OVERVIEW", "DEFLATE");
    const std::string count = io::gdal().CPLGetConfigOption("GDAL_NUM_THREADS", "ALL_CPUS");  // a copy: set below
    ConfigOption threads("GDAL_NUM_THREADS", count.c_str());
    io::GdalDataset vrt(io::gdal().GDALOpen(temp_vrt.c_str(), GA_ReadOnly));
    if (!vrt) session.fail(FT_ERR_IO, "GDAL could not reopen the mosaic '" + final_vrt + "'");
    if (io::gdal().GDALBuildOverviews(vrt.get(), "AVERAGE", int(factors.size()), factors.data(), 0, nullptr, nullptr, nullptr) !=
        CE_None)
      session.fail(FT_ERR_IO, "GDAL could not build the overviews of '" + final_vrt + "'");
  }
  if (!factors.empty()) fs::rename(platform::fs_path(temp_vrt + ".ovr"), platform::fs_path(final_vrt + ".ovr"));
  else fs::remove(platform::fs_path(final_vrt + ".ovr"));
  fs::rename(platform::fs_path(temp_vrt), final_path);
}

}  // namespace

void write_mosaic_vrt(const TileSpec& spec, const std::string& dir) {
  io::gdal("the VRT mosaic of tile set '" + dir + "'");
  std::vector<std::string> files;
  for (int32_t row = 0; row < spec.grid.rows(); ++row)
    for (int32_t col = 0; col < spec.grid.columns(); ++col) files.push_back(tile_file_name(spec, col, row));
  build_vrt(spec, dir, files, kMosaicName, spec.format == TileFormat::png16, true);
}

void write_map_vrt(const TileSpec& spec, const std::string& dir, int k) {
  io::gdal("the map mosaics of tile set '" + dir + "'");
  std::vector<std::string> files;
  for (int32_t row = 0; row < spec.grid.rows(); ++row)
    for (int32_t col = 0; col < spec.grid.columns(); ++col) files.push_back(map_file_name(spec, k, col, row));
  build_vrt(spec, dir, files, map_vrt_name(k), false, false);
}

Heightfield read_mosaic_preview(const std::string& dir, int32_t max_side) {
  check_int_range("preview side", max_side, 2, 65536);
  io::gdal("a preview of tile set '" + dir + "' (its VRT mosaic)");
  const std::string path = platform::join_path(dir, kMosaicName);
  io::GdalSession session;
  io::GdalDataset ds(io::gdal().GDALOpen(path.c_str(), GA_ReadOnly));
  if (!ds) session.fail(FT_ERR_IO, "cannot open the tile set's mosaic '" + path + "' (is the set finished?)");
  const int w = io::gdal().GDALGetRasterXSize(ds.get()), h = io::gdal().GDALGetRasterYSize(ds.get());
  const double k = std::min(1.0, double(max_side) / double(std::max(w, h)));
  const int32_t pw = std::max(2, int32_t(std::lround(w * k))), ph = std::max(2, int32_t(std::lround(h * k)));
  Heightfield hf(pw, ph);
  GDALRasterBandH band = io::gdal().GDALGetRasterBand(ds.get(), 1);
  if (io::gdal().GDALRasterIO(band, GF_Read, 0, 0, w, h, hf.data(), pw, ph, GDT_Float32, 0, 0) != CE_None)
    session.fail(FT_ERR_IO, "cannot read the mosaic '" + path + "'");
  int has = 0;
  const double offset = io::gdal().GDALGetRasterOffset(band, &has), scale = io::gdal().GDALGetRasterScale(band, nullptr);
  for (size_t i = 0; i < hf.size(); ++i) hf.data()[i] = float(offset + scale * hf.data()[i]);
  if (const char* ws = io::gdal().GDALGetMetadataItem(ds.get(), "FRACTERRA_WORLD_SIZE", nullptr)) hf.set_world_size(std::atof(ws));
  return hf;
}

}  // namespace ft::tiles
