// SPDX-License-Identifier: GPL-3.0-or-later
// The equirectangular layout (fracterra/planet.h): pixel (i, j) of W x H at
// longitude -180 + (i + 0.5) 360 / W and latitude 90 - (j + 0.5) 180 / H
// degrees, georeferenced in EPSG:4326 so GDAL writes it as a world map.
#pragma once

#include <array>
#include <cstdint>

#include "core/heightfield.hpp"
#include "planet/planet.hpp"

namespace ft::planet {

// The unit vector of pixel (i, j) of a width x height map.
std::array<double, 3> equirect_point(int64_t i, int64_t j, int32_t width, int32_t height);
Heightfield equirect(const Planet& planet, int32_t width, int32_t height);

}  // namespace ft::planet
