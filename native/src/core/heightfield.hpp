// SPDX-License-Identifier: GPL-3.0-or-later
// A float32 heightfield, row-major: sample (x, y) is at y * width + x.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "core/buffer.hpp"

namespace ft {

struct HeightStats {
  double min = 0, max = 0, mean = 0, std = 0;
};

// Where a heightfield lies on the Earth, when it came from a georeferenced
// raster: kept so that what is written from it is georeferenced too.
struct GeoReference {
  std::string crs_wkt;                // the coordinate system as WKT ("" if none)
  std::array<double, 6> transform{};  // GDAL's geotransform: pixel -> map coordinates
  bool has_transform = false;
  bool empty() const noexcept { return crs_wkt.empty() && !has_transform; }
};

class Heightfield {
 public:
  Heightfield() = default;
  // Checks the size against the memory cap before allocating; samples are
  // left uninitialised (every generator writes all of them).
  Heightfield(int32_t width, int32_t height);

  int32_t width() const noexcept { return width_; }
  int32_t height() const noexcept { return height_; }
  size_t size() const noexcept { return samples_.size(); }
  float* data() noexcept { return samples_.data(); }
  const float* data() const noexcept { return samples_.data(); }
  float& at(int32_t x, int32_t y) noexcept { return samples_[size_t(y) * width_ + x]; }
  float at(int32_t x, int32_t y) const noexcept { return samples_[size_t(y) * width_ + x]; }

  HeightStats stats() const;
  // Extent along x in scene units that the samples cover (0: unknown).
  double world_size() const noexcept { return world_size_; }
  void set_world_size(double size) noexcept { world_size_ = size; }
  const GeoReference& georef() const noexcept { return georef_; }
  void set_georef(GeoReference g) { georef_ = std::move(g); }

 private:
  int32_t width_ = 0, height_ = 0;
  double world_size_ = 0.0;
  GeoReference georef_;
  Buffer<float> samples_;
};

}  // namespace ft
