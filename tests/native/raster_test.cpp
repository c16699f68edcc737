// SPDX-License-Identifier: GPL-3.0-or-later
// Rasters in and out: GeoTIFF/COG and OpenEXR round trips are exact to the
// bit, RAW16 within half a step of 16 bits; georeferencing survives (checked
// by GDAL's own gdalinfo -json); nodata is refused with its count or filled;
// malformed and truncated files are refused without output, and GDAL never
// prints behind our back.
#include <gtest/gtest.h>

#include <cpl_string.h>
#include <gdal.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "io/atomic_file.hpp"
#include "io/exr.hpp"
#include "io/heightfield_io.hpp"
#include "io/raw16.hpp"

namespace ft {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("ft_raster_test_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}
std::string tmp(const std::string& name) { return (temp_dir() / name).string(); }

// Heights over many binades, negative and positive, with every mantissa bit
// in play: a lossy path (a half float, an 8-bit step, a rounding) shows.
Heightfield random_heights(int32_t w, int32_t h, uint64_t seed) {
  Heightfield hf(w, h);
  for (int32_t y = 0; y < h; ++y)
    for (int32_t x = 0; x < w; ++x) {
      const Counter c{uint32_t(y), 0, Stream::kFirstUser};
      const uint32_t hi = random_bits(seed, c, 2 * uint64_t(x)), lo = random_bits(seed, c, 2 * uint64_t(x) + 1);
      const double u = bits_to_unit_double(hi, lo);
      hf.at(x, y) = float((u - 0.3) * std::ldexp(1.0, int(lo & 15) - 4));
    }
  hf.set_world_size(1234.5);
  return hf;
}

void expect_same_bits(const Heightfield& a, const Heightfield& b) {
  ASSERT_EQ(a.width(), b.width());
  ASSERT_EQ(a.height(), b.height());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0);
}

ft_status status_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.status();
  }
  return FT_OK;
}

std::string run(const std::string& cmd) {
  std::string out;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return out;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
  ::pclose(p);
  return out;
}

// A georeferenced raster written by GDAL itself (not by us): UTM 32N, 30 m
// pixels, Int16 with a nodata value, as a national DEM would be.
std::string make_georeferenced(const std::string& name, int w, int h, bool with_holes) {
  GDALAllRegister();
  const std::string path = tmp(name);
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 1, GDT_Int16, nullptr);
  double gt[6] = {500000, 30, 0, 5500000, 0, -30};
  GDALSetGeoTransform(ds, gt);
  GDALSetProjection(ds, "EPSG:32632");
  GDALRasterBandH b = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(b, -32768);
  std::vector<int16_t> v(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) v[size_t(y) * w + x] = int16_t(100 + 3 * x + 2 * y + (x * y) % 7);
  if (with_holes) v[size_t(h / 2) * w + w / 2] = v[0] = v[1] = -32768;
  EXPECT_EQ(GDALRasterIO(b, GF_Write, 0, 0, w, h, v.data(), w, h, GDT_Int16, 0, 0), CE_None);
  GDALClose(ds);
  return path;
}

TEST(Raster, GeoTiffRoundTripIsBitExact) {
  const Heightfield hf = random_heights(37, 23, 7);
  io::write_heightfield(hf, tmp("a.tif"));
  const Heightfield back = io::read_heightfield(tmp("a.tif"));
  expect_same_bits(hf, back);
  EXPECT_DOUBLE_EQ(back.world_size(), 1234.5);
}

TEST(Raster, OpenExrRoundTripIsBitExact) {
  const Heightfield hf = random_heights(41, 19, 8);
  io::write_heightfield(hf, tmp("a.exr"));
  const Heightfield back = io::read_heightfield(tmp("a.exr"));
  expect_same_bits(hf, back);
  EXPECT_DOUBLE_EQ(back.world_size(), 1234.5);
}

TEST(Raster, Raw16RoundTripIsWithinHalfAStep) {
  const Heightfield hf = random_heights(33, 17, 9);
  const HeightStats s = hf.stats();
  for (const char* ext : {".raw", ".r16"}) {
    const std::string path = tmp(std::string("a") + ext);
    io::write_heightfield(hf, path);
    EXPECT_EQ(fs::file_size(path), 33u * 17u * 2u);
    const Heightfield back = io::read_heightfield(path);
    ASSERT_EQ(back.width(), 33);
    ASSERT_EQ(back.height(), 17);
    // Half a step of 65535 over the range, plus float32 rounding of the
    // reconstructed value (a few ulps of the largest magnitude).
    const double lsb = (s.max - s.min) / 65535.0;
    const double ulp = 4 * std::max(std::abs(s.min), std::abs(s.max)) * 0x1.0p-24;
    double worst = 0;
    for (size_t i = 0; i < hf.size(); ++i) worst = std::max(worst, std::abs(double(back.data()[i]) - hf.data()[i]));
    EXPECT_LE(worst, 0.5 * lsb + ulp) << ext;
    EXPECT_GT(worst, 0.0) << "16 bits cannot hold these floats exactly: the test would not see a loss";
    std::ifstream side(io::raw16_sidecar_path(path));
    const auto j = nlohmann::json::parse(side);
    EXPECT_EQ(j["width"], 33);
    EXPECT_EQ(j["height"], 17);
    EXPECT_EQ(j["byte_order"], "little");
    EXPECT_DOUBLE_EQ(j["height_range"].get<double>(), s.max - s.min);
    EXPECT_DOUBLE_EQ(j["world_size"].get<double>(), 1234.5);
  }
}

TEST(Raster, Raw16IsLittleEndianWithZeroAtTheLowest) {
  Heightfield hf(2, 1);
  hf.at(0, 0) = -5.0f;
  hf.at(1, 0) = 7.0f;
  io::write_heightfield(hf, tmp("two.raw"));
  const std::string bytes = io::read_file(tmp("two.raw"));
  ASSERT_EQ(bytes.size(), 4u);
  EXPECT_EQ(bytes, std::string("\x00\x00\xff\xff", 4));
}

TEST(Raster, GeoTiffIsCloudOptimizedWithOverviews) {
  const Heightfield hf = random_heights(1100, 700, 10);
  io::write_heightfield(hf, tmp("big.tif"));
  const auto j = nlohmann::json::parse(run("gdalinfo -json " + tmp("big.tif")));
  EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["LAYOUT"], "COG");
  EXPECT_EQ(j["metadata"]["IMAGE_STRUCTURE"]["COMPRESSION"], "DEFLATE");
  EXPECT_EQ(j["bands"][0]["type"], "Float32");
  EXPECT_GE(j["bands"][0]["overviews"].size(), 1u);
}

TEST(Raster, GeoreferencingSurvivesAsGdalinfoSeesIt) {
  const std::string src = make_georeferenced("utm.tif", 40, 30, false);
  const Heightfield hf = io::read_heightfield(src);
  EXPECT_DOUBLE_EQ(hf.world_size(), 39 * 30.0);  // metres between the first and last sample centres
  EXPECT_FLOAT_EQ(hf.at(5, 4), 100 + 15 + 8 + 20 % 7);
  io::write_heightfield(hf, tmp("utm-out.tif"));
  const auto a = nlohmann::json::parse(run("gdalinfo -json " + src));
  const auto b = nlohmann::json::parse(run("gdalinfo -json " + tmp("utm-out.tif")));
  EXPECT_EQ(b["geoTransform"], a["geoTransform"]);
  EXPECT_EQ(b["coordinateSystem"]["wkt"], a["coordinateSystem"]["wkt"]);
  EXPECT_EQ(b["stac"]["proj:epsg"], 32632);
}

TEST(Raster, GeographicPixelsBecomeMetresForTheWorldSize) {
  Heightfield hf = random_heights(11, 11, 3);
  GeoReference g;
  g.crs_wkt = "GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,298.257223563]],PRIMEM[\"Greenwich\",0],"
              "UNIT[\"degree\",0.0174532925199433]]";
  g.transform = {6.0, 0.01, 0, 60.055, 0, -0.01};  // centre latitude 60.055 - 11 / 2 x 0.01 = 60: cos = 1/2
  g.has_transform = true;
  hf.set_georef(g);
  io::write_heightfield(hf, tmp("geo.tif"));
  const double metres_per_degree = 6378137 * 3.14159265358979323846 / 180;
  EXPECT_NEAR(io::read_heightfield(tmp("geo.tif")).world_size(), 10 * 0.01 * metres_per_degree * 0.5, 1e-6);
}

TEST(Raster, EsriAsciiGridIsReadThroughGdal) {
  const std::string path = tmp("grid.asc");
  std::ofstream(path) << "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 10\nNODATA_value -9999\n"
                         "1 2 3\n4 5.5 6\n";
  const Heightfield hf = io::read_heightfield(path);
  ASSERT_EQ(hf.width(), 3);
  ASSERT_EQ(hf.height(), 2);
  EXPECT_FLOAT_EQ(hf.at(1, 1), 5.5f);
  EXPECT_DOUBLE_EQ(hf.world_size(), 20.0);
}

TEST(Raster, NodataIsRefusedWithItsCount) {
  const std::string src = make_georeferenced("holes.tif", 20, 10, true);
  try {
    io::read_heightfield(src);
    FAIL() << "nodata was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_FORMAT);
    EXPECT_NE(std::string(e.what()).find("3 nodata samples of 200"), std::string::npos) << e.what();
  }
}

TEST(Raster, NodataFillKeepsValidSamplesAndStaysInTheirRange) {
  const std::string src = make_georeferenced("holes2.tif", 20, 10, true);
  const Heightfield hf = io::read_heightfield(src, io::NodataPolicy::fill);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 20; ++x) {
      const bool hole = (y == 0 && x < 2) || (y == 5 && x == 10);
      if (hole) continue;
      EXPECT_FLOAT_EQ(hf.at(x, y), 100 + 3 * x + 2 * y + (x * y) % 7);
    }
  // Inverse-distance weights are convex: a filled sample lies within the
  // range of the valid samples around it.
  EXPECT_GE(hf.at(10, 5), 100 + 3 * 9 + 2 * 4);
  EXPECT_LE(hf.at(10, 5), 100 + 3 * 11 + 2 * 6 + 6);
  EXPECT_GE(hf.at(0, 0), 100.0f);
  EXPECT_LE(hf.at(0, 0), 100 + 3 * 3 + 2 * 2 + 6.0f);
}

// GDALFillNodata keeps its work rasters in GTiff files in the current
// directory unless told otherwise: a fill from Blender (whose directory may
// not be writable) failed, and a killed process left three files behind. In
// a directory that no longer exists no file can be made, even by root.
TEST(Raster, NodataFillWritesNoFileInTheCurrentDirectory) {
  const std::string src = make_georeferenced("holes3.tif", 20, 10, true);
  const fs::path here = fs::current_path();
  const fs::path gone = fs::path(tmp("gone-dir"));
  fs::create_directories(gone);
  fs::current_path(gone);
  fs::remove(gone);
  float filled = 0;
  try {
    filled = io::read_heightfield(src, io::NodataPolicy::fill).at(10, 5);
  } catch (const Error& e) {
    fs::current_path(here);
    FAIL() << "the fill needed the current directory: " << e.what();
  }
  fs::current_path(here);
  EXPECT_GE(filled, 100 + 3 * 9 + 2 * 4);
}

// The fill looks 256 samples from each hole (its cost grows with that
// distance, gdal_reader.cpp): a hole wider than twice that keeps samples out
// of reach, and they are refused with their count instead of left NaN.
TEST(Raster, NodataFillRefusesHolesBeyondItsReach) {
  GDALAllRegister();
  const int w = 3, h = 600;
  const std::string path = tmp("far_holes.tif");
  GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), w, h, 1, GDT_Float32, nullptr);
  std::vector<float> v(size_t(w) * h, -9999.0f);
  for (int x = 0; x < w; ++x) v[size_t(x)] = 10.0f + x;  // only the first row is valid
  GDALRasterBandH b = GDALGetRasterBand(ds, 1);
  GDALSetRasterNoDataValue(b, -9999);
  EXPECT_EQ(GDALRasterIO(b, GF_Write, 0, 0, w, h, v.data(), w, h, GDT_Float32, 0, 0), CE_None);
  GDALClose(ds);
  try {
    io::read_heightfield(path, io::NodataPolicy::fill);
    FAIL() << "a hole beyond the fill's reach was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_FORMAT);
    // Rows 257..599 are more than 256 samples from row 0.
    EXPECT_NE(std::string(e.what()).find(std::to_string((h - 257) * w) + " nodata samples farther than 256"),
              std::string::npos)
        << e.what();
  }
}

// OpenEXR allocates an attribute's declared size before reading it: a tiny
// file whose attribute claims 2 GB is refused before OpenEXR sees it (the
// fuzz finding tests/fuzz/regressions/exr/attribute_50mb_in_609_bytes.exr).
TEST(Raster, AnExrAttributeLargerThanTheFileIsRefusedBeforeReading) {
  std::string bytes("v/1\x01\x02\0\0\0channels\0chlist\0", 24);
  const int32_t huge = 0x7fffffff;
  bytes.append(reinterpret_cast<const char*>(&huge), 4);
  bytes.append("Y\0\0\0\0\0", 6);
  try {
    io::decode_exr(bytes);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.status(), FT_ERR_FORMAT);
    EXPECT_NE(std::string(e.what()).find("an attribute says it holds 2147483647 bytes, and 6 follow"), std::string::npos)
        << e.what();
  }
}

TEST(Raster, MalformedAndTruncatedFilesAreRefusedQuietly) {
  io::write_heightfield(random_heights(300, 200, 4), tmp("good.tif"));
  io::write_heightfield(random_heights(300, 200, 4), tmp("good.exr"));
  for (const char* ext : {".tif", ".exr"}) {
    const std::string good = io::read_file(tmp(std::string("good") + ext));
    // (A COG repeats the last 4 bytes of each tile after it: cutting fewer
    // loses nothing, and GDAL rightly reads the file.)
    for (size_t keep : {size_t(0), size_t(8), good.size() / 2, good.size() - 64}) {
      const std::string path = tmp(std::string("cut") + ext);
      io::write_file_atomically(path, good.substr(0, keep));
      testing::internal::CaptureStderr();
      const ft_status st = status_of([&] { io::read_heightfield(path); });
      EXPECT_EQ(testing::internal::GetCapturedStderr(), "") << ext << " cut at " << keep;
      EXPECT_EQ(st, FT_ERR_FORMAT) << ext << " cut at " << keep;
    }
  }
  io::write_file_atomically(tmp("junk.hgt"), std::string(1000, 'x'));
  EXPECT_EQ(status_of([&] { io::read_heightfield(tmp("junk.hgt")); }), FT_ERR_FORMAT);
  EXPECT_EQ(status_of([&] { io::read_heightfield(tmp("absent.tif")); }), FT_ERR_IO);
  // RAW16: one byte short of what the sidecar promises; no sidecar and not a square.
  io::write_heightfield(random_heights(8, 8, 5), tmp("r.raw"));
  io::write_file_atomically(tmp("r.raw"), io::read_file(tmp("r.raw")).substr(1));
  EXPECT_EQ(status_of([&] { io::read_heightfield(tmp("r.raw")); }), FT_ERR_FORMAT);
  io::write_file_atomically(tmp("lone.r16"), std::string(10, '\0'));
  EXPECT_EQ(status_of([&] { io::read_heightfield(tmp("lone.r16")); }), FT_ERR_FORMAT);
  io::write_file_atomically(tmp("bad.raw.json"), "{\"width\": 1e30}");
  io::write_file_atomically(tmp("bad.raw"), std::string(8, '\0'));
  EXPECT_EQ(status_of([&] { io::read_heightfield(tmp("bad.raw")); }), FT_ERR_FORMAT);
}

TEST(Raster, FailedWritesLeaveNoFile) {
  Heightfield hf = random_heights(9, 9, 6);
  hf.at(4, 4) = std::nanf("");
  for (const char* ext : {".tif", ".exr", ".raw"}) {
    const std::string path = tmp(std::string("nan") + ext);
    EXPECT_EQ(status_of([&] { io::write_heightfield(hf, path); }), FT_ERR_INVALID_ARGUMENT) << ext;
    EXPECT_FALSE(fs::exists(path)) << ext;
    EXPECT_FALSE(fs::exists(path + ".json")) << ext;
  }
  for (const char* ext : {".tif", ".exr", ".raw"})
    EXPECT_EQ(status_of([&] { io::write_heightfield(random_heights(3, 3, 1), tmp("no/such/dir/x") + ext); }), FT_ERR_IO);
  for (const auto& e : fs::directory_iterator(temp_dir()))
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
}

}  // namespace
}  // namespace ft
