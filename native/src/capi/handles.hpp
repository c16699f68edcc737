// SPDX-License-Identifier: GPL-3.0-or-later
// The opaque C handles are thin wrappers around the C++ results.
#pragma once

#include "core/heightfield.hpp"
#include "core/mesh.hpp"
#include "core/polyline_set.hpp"
#include "hydrology/hydrology.hpp"

struct ft_heightfield {
  ft::Heightfield hf;
};

struct ft_polylines {
  ft::PolylineSet set;
};

struct ft_mesh {
  ft::Mesh mesh;
};

struct ft_river_network {
  ft::hydrology::RiverNetwork net;
};
