// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/equirect.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "core/error.hpp"
#include "planet/cube_sampler.hpp"

namespace ft::planet {
namespace {

// WGS 84 (EPSG:4326) as WKT1, the form every GDAL version reads. Longitude
// first in the geotransform, as GeoTIFF stores it.
constexpr const char* kWgs84Wkt =
    "GEOGCS[\"WGS 84\",DATUM[\"WGS_1984\",SPHEROID[\"WGS 84\",6378137,298.257223563,AUTHORITY[\"EPSG\",\"7030\"]],"
    "AUTHORITY[\"EPSG\",\"6326\"]],PRIMEM[\"Greenwich\",0,AUTHORITY[\"EPSG\",\"8901\"]],"
    "UNIT[\"degree\",0.0174532925199433,AUTHORITY[\"EPSG\",\"9122\"]],AUTHORITY[\"EPSG\",\"4326\"]]";

}  // namespace

std::array<double, 3> equirect_point(int64_t i, int64_t j, int32_t width, int32_t height) {
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double lon = (-180.0 + (double(i) + 0.5) * 360.0 / width) * kDeg;
  const double lat = (90.0 - (double(j) + 0.5) * 180.0 / height) * kDeg;
  const double c = std::cos(lat);
  return {c * std::cos(lon), c * std::sin(lon), std::sin(lat)};
}

Heightfield equirect(const Planet& planet, int32_t width, int32_t height) {
  check_int_range("width", width, 2, 65536);
  check_int_range("height", height, 2, 65536);
  Heightfield hf(width, height);
  hf.set_world_size(2.0 * std::numbers::pi * planet.config().radius);  // the equator's length
  GeoReference g;
  g.crs_wkt = kWgs84Wkt;
  g.transform = {-180.0, 360.0 / width, 0.0, 90.0, 0.0, -180.0 / height};
  g.has_transform = true;
  hf.set_georef(g);
  if (planet.midpoint()) {
    // The cube-sphere at the first level as fine as the map's pixels
    // (2 / 2^level radians at a face's centre <= 2 pi / width and pi / height),
    // interpolated; its first 80 % of the progress.
    const int level = sampler_level_for(std::min(2.0 * std::numbers::pi / width, std::numbers::pi / height));
    const ProgressPart faces(planet.config().progress, 0.0, 0.8), pixels(planet.config().progress, 0.8, 0.2);
    const CubeSampler sampler(planet.midpoint_config(), level, planet.config().threads, faces.progress());
    fill_rows(width, height, planet.config().threads, pixels.progress(),
              [&](int32_t y, float* row) {
                for (int32_t x = 0; x < width; ++x) {
                  const auto p = equirect_point(x, y, width, height);
                  row[x] = sampler.height(p[0], p[1], p[2]);
                }
                planet.raise_to_sea(width, row);
              },
              hf.data());
    return hf;
  }
  fill_rows(width, height, planet.config().threads, planet.config().progress,
            [&](int32_t y, float* row) {
              Directions d{size_t(width)};
              for (int32_t x = 0; x < width; ++x) d.set(size_t(x), equirect_point(x, y, width, height));
              planet.heights(d, row);
            },
            hf.data());
  return hf;
}

}  // namespace ft::planet
