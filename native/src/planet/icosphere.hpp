// SPDX-License-Identifier: GPL-3.0-or-later
// The icosphere layout: a regular icosahedron whose triangles are split in
// four `level` times, every new vertex the normalised middle of its edge
// (10 4^n + 2 vertices, 20 4^n triangles, counter-clockwise seen from
// outside), at radius + vertical_scale x height. Its cells are nearly equal
// (the largest 1.2 times the smallest at level 6), where the cube-sphere's
// differ by 5 between a face's centre and corner.
#pragma once

#include <cstdint>
#include <vector>

#include "core/mesh.hpp"
#include "planet/planet.hpp"

namespace ft::planet {

inline constexpr int kMaxIcosphereLevel = 10;

int64_t icosphere_vertex_count(int level);
int64_t icosphere_face_count(int level);

// The mesh in metres. An fBm planet's heights are the field's at the
// vertices; a midpoint planet's are its cube-sphere of level + 1 (spacing
// at most the icosphere's edge, 63.4 / 2^level degrees) interpolated
// (cube_sampler.hpp). `heights` (if not null) gets each vertex's height.
Mesh icosphere_mesh(const Planet& planet, int level, double vertical_scale, std::vector<float>* heights = nullptr);

}  // namespace ft::planet
