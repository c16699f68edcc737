// SPDX-License-Identifier: GPL-3.0-or-later
// Lakes: every depression filled to its spill level by Priority-Flood from
// the base levels (Barnes, Lehman & Mulla 2014, Algorithm 1 for the levels
// and Algorithm 3's epsilon steps for a surface that drains), then labelled.
// Two 8-neighbours under water have the same level (a lower one would drain
// the higher through their shared edge), so a lake is an 8-connected set of
// flooded cells; one is a lake when some of it lies deeper than the minimum
// depth (its shoreline, lake_rings.cpp, runs where the water is that deep).
#include <algorithm>
#include <cmath>
#include <vector>

#include "erosion/priority_flood.hpp"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {

Water fill_lakes(const erosion::D8Grid& g, const float* z, const std::vector<uint8_t>& sea,
                 const std::vector<int32_t>& sinks, double min_lake_area, double min_depth) {
  const size_t n = g.size();
  Water w;
  w.level.assign(z, z + n);
  w.graded.assign(z, z + n);
  w.label.assign(n, kLand);
  w.base.assign(n, 0);
  std::vector<int32_t> seeds;
  for (size_t i = 0; i < n; ++i)
    if (sea[i]) seeds.push_back(int32_t(i));
  if (!g.periodic) {
    const std::vector<int32_t> edges = erosion::edge_cells(g);
    seeds.insert(seeds.end(), edges.begin(), edges.end());
  }
  for (const int32_t s : sinks) seeds.push_back(s);
  if (seeds.empty()) seeds.push_back(int32_t(std::min_element(z, z + n) - z));  // a torus drains to its lowest
  for (const int32_t s : seeds) w.base[s] = 1;
  // Keyed by the graded surface (the seeds' graded heights are their own).
  erosion::priority_flood(g, seeds, w.graded.data(), [&](int32_t c, int32_t j) {
    w.level[j] = std::max(z[j], w.level[c]);
    if (w.graded[j] > w.graded[c]) return false;
    w.graded[j] = std::nextafter(w.graded[c], INFINITY);
    return true;
  });
  // Label the flooded cells, 8-connected, in index order. A depression with
  // no cell under water by more than min_depth is a puddle too: as a lake
  // it would be water flush with the ground (a hollow filled up to a plain's
  // level is mostly such a rim).
  w.min_depth = min_depth;
  const double cell_area = g.spacing * g.spacing;
  std::vector<int32_t> todo, members;
  std::vector<uint8_t> seen(n, 0);
  for (size_t s = 0; s < n; ++s) {
    if (seen[s] || w.base[s] || !(w.level[s] > z[s])) continue;
    members.clear();
    todo.assign(1, int32_t(s));
    seen[s] = 1;
    double volume = 0, deepest = 0;
    while (!todo.empty()) {
      const int32_t c = todo.back();
      todo.pop_back();
      members.push_back(c);
      volume += (double(w.level[c]) - double(z[c])) * cell_area;
      deepest = std::max(deepest, double(w.level[c]) - double(z[c]));
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(c % g.width, c / g.width, k);
        if (j < 0 || seen[j] || w.base[j] || !(w.level[j] > z[j])) continue;
        seen[j] = 1;
        todo.push_back(int32_t(j));
      }
    }
    const double area = double(members.size()) * cell_area;
    if (area < min_lake_area || !(deepest > min_depth)) continue;  // a puddle: rivers pass through it
    Lake lake;
    lake.level = w.level[s];
    lake.area = area;
    lake.volume = volume;
    lake.cells = int32_t(members.size());
    const int32_t id = int32_t(w.lakes.size());
    for (const int32_t c : members) w.label[c] = id;
    w.lakes.push_back(lake);
  }
  for (size_t i = 0; i < n; ++i)
    if (sea[i]) w.label[i] = kSea;
  return w;
}

}  // namespace ft::hydrology
