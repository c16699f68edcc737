// SPDX-License-Identifier: GPL-3.0-or-later
#include "planet/icosphere.hpp"

#include <array>
#include <cmath>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "core/memory.hpp"
#include "planet/cube_sampler.hpp"
#include "planet/cube_sphere.hpp"

namespace ft::planet {
namespace {

using Triangle = std::array<int32_t, 3>;

// The 12 vertices (0, +-1, +-phi) and its cyclic turns, and the 20 faces,
// each turned below to face outwards.
void icosahedron(Directions* u, std::vector<Triangle>* faces) {
  const double phi = (1.0 + std::sqrt(5.0)) / 2.0, len = std::sqrt(1.0 + phi * phi);
  const double a = 1.0 / len, b = phi / len;
  const std::array<double, 3> v[12] = {{-a, b, 0}, {a, b, 0}, {-a, -b, 0}, {a, -b, 0}, {0, -a, b}, {0, a, b},
                                       {0, -a, -b}, {0, a, -b}, {b, 0, -a}, {b, 0, a}, {-b, 0, -a}, {-b, 0, a}};
  for (size_t i = 0; i < 12; ++i) u->set(i, v[i]);
  *faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
            {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Triangle& t : *faces) {
    const auto p = [&](int k) { return std::array<double, 3>{u->x[size_t(t[size_t(k)])], u->y[size_t(t[size_t(k)])], u->z[size_t(t[size_t(k)])]}; };
    const auto A = p(0), B = p(1), C = p(2);
    const double e1[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]}, e2[3] = {C[0] - A[0], C[1] - A[1], C[2] - A[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    if (n[0] * (A[0] + B[0] + C[0]) + n[1] * (A[1] + B[1] + C[1]) + n[2] * (A[2] + B[2] + C[2]) < 0)
      std::swap(t[1], t[2]);
  }
}

}  // namespace

int64_t icosphere_vertex_count(int level) { return 10 * (int64_t(1) << (2 * level)) + 2; }
int64_t icosphere_face_count(int level) { return 20 * (int64_t(1) << (2 * level)); }

Mesh icosphere_mesh(const Planet& planet, int level, double vertical_scale, std::vector<float>* heights) {
  check_int_range("level", level, 0, kMaxIcosphereLevel);
  check_vertical_scale(vertical_scale);
  const int64_t nv = icosphere_vertex_count(level), nf = icosphere_face_count(level);
  // Directions, positions and heights; triangles (two generations at once);
  // the last split's edge map (its edges, ~48 bytes an entry).
  check_allocation(checked_bytes(uint64_t(nv), 24 + 12 + 4) + checked_bytes(uint64_t(nf), 12 * 2) +
                       checked_bytes(uint64_t(nf), 48 * 3 / 8),
                   "an icosphere mesh of level " + std::to_string(level));
  Directions u{static_cast<size_t>(nv)};
  std::vector<Triangle> faces;
  icosahedron(&u, &faces);
  int64_t count = 12;
  for (int l = 0; l < level; ++l) {
    std::unordered_map<uint64_t, int32_t> middle;
    middle.reserve(faces.size() * 3 / 2);
    auto mid = [&](int32_t a, int32_t b) {
      const uint64_t key = (uint64_t(uint32_t(std::min(a, b))) << 32) | uint32_t(std::max(a, b));
      const auto [it, fresh] = middle.try_emplace(key, int32_t(count));
      if (fresh) {
        if (count == nv) fail(FT_ERR_INTERNAL, "icosphere: more than " + std::to_string(nv) + " vertices");
        const double x = u.x[size_t(a)] + u.x[size_t(b)], y = u.y[size_t(a)] + u.y[size_t(b)],
                     z = u.z[size_t(a)] + u.z[size_t(b)];
        const double len = std::sqrt(x * x + y * y + z * z);
        u.set(size_t(count++), {x / len, y / len, z / len});
      }
      return it->second;
    };
    std::vector<Triangle> finer;
    finer.reserve(faces.size() * 4);
    for (const Triangle& t : faces) {
      const int32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({ab, t[1], bc});
      finer.push_back({ca, bc, t[2]});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
    planet.config().progress.report(0.1 * (l + 1) / level);
  }
  if (count != nv || int64_t(faces.size()) != nf)
    fail(FT_ERR_INTERNAL, "icosphere: " + std::to_string(count) + " vertices, " + std::to_string(faces.size()) +
                              " faces at level " + std::to_string(level));
  // The splits took the bar's first 10 %; the heights take 80, the positions 10.
  const ProgressPart height_part(planet.config().progress, 0.1, 0.8), place_part(planet.config().progress, 0.9, 0.1);
  std::vector<float> h;
  if (planet.midpoint()) {
    const CubeSampler sampler(planet.midpoint_config(), std::min(level + 1, kMaxLevel), planet.config().threads,
                              height_part.progress());
    h.resize(size_t(nv));
    for (int64_t v = 0; v < nv; ++v) h[size_t(v)] = sampler.height(u.x[size_t(v)], u.y[size_t(v)], u.z[size_t(v)]);
    planet.raise_to_sea(nv, h.data());
  } else {
    h = heights_in_rows(planet, u, height_part.progress());
  }
  Mesh mesh;
  mesh.positions.resize(size_t(3 * nv));
  place_on_sphere(u, h, planet.config().radius, vertical_scale, planet.config().threads, place_part.progress(),
                  mesh.positions.data());
  mesh.face_sizes.assign(size_t(nf), 3);
  mesh.face_indices.reserve(size_t(3 * nf));
  for (const Triangle& t : faces) mesh.face_indices.insert(mesh.face_indices.end(), t.begin(), t.end());
  if (heights) *heights = std::move(h);
  return mesh;
}

}  // namespace ft::planet
