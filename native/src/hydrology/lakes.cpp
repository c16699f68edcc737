// Lakes: every depression filled to its spill level by Priority-Flood from
// the base levels (Barnes, Lehman & Mulla 2014, Algorithm 1 for the levels
// and Algorithm 3's epsilon steps for a surface that drains), then labelled.
// Two 8-neighbours under water have the same level (a lower one would drain
// the higher through their shared edge), so a lake is an 8-connected set of
// flooded cells.
#include <algorithm>
#include <cmath>
#include <vector>

#include "erosion/radix_heap.hpp"
#include "hydrology/hydrology.hpp"

namespace ft::hydrology {

Water fill_lakes(const erosion::D8Grid& g, const float* z, const std::vector<uint8_t>& sea,
                 const std::vector<int32_t>& sinks, double min_lake_area) {
  const size_t n = g.size();
  Water w;
  w.level.assign(z, z + n);
  w.graded.assign(z, z + n);
  w.label.assign(n, kLand);
  w.base.assign(n, 0);
  std::vector<uint8_t> closed(n, 0);
  erosion::RadixHeap open;
  std::vector<int32_t> fifo;  // raised cells, first in first out (Algorithm 3's pit queue)
  size_t head = 0;
  auto seed = [&](size_t i) {
    w.base[i] = 1;
    if (!closed[i]) {
      closed[i] = 1;
      open.push(z[i], int32_t(i));
    }
  };
  std::vector<int32_t> seeds;
  for (size_t i = 0; i < n; ++i)
    if (sea[i]) seeds.push_back(int32_t(i));
  if (!g.periodic) {
    for (int32_t x = 0; x < g.width; ++x)
      seeds.push_back(x), seeds.push_back(int32_t(size_t(g.height - 1) * g.width + x));
    for (int32_t y = 0; y < g.height; ++y)
      seeds.push_back(int32_t(size_t(y) * g.width)), seeds.push_back(int32_t(size_t(y) * g.width + g.width - 1));
  }
  for (const int32_t s : sinks) seeds.push_back(s);
  if (seeds.empty()) seeds.push_back(int32_t(std::min_element(z, z + n) - z));  // a torus drains to its lowest
  for (const int32_t s : seeds) seed(size_t(s));
  while (!open.empty() || head < fifo.size()) {
    int32_t c;
    if (head < fifo.size()) {
      c = fifo[head++];
      if (head == fifo.size()) fifo.clear(), head = 0;
    } else {
      c = open.pop();
    }
    const int32_t cx = c % g.width, cy = c / g.width;
    for (int k = 0; k < 8; ++k) {
      const int64_t j = g.neighbour(cx, cy, k);
      if (j < 0 || closed[j]) continue;
      closed[j] = 1;
      w.level[j] = std::max(z[j], w.level[c]);
      if (w.graded[j] <= w.graded[c]) {
        w.graded[j] = std::nextafter(w.graded[c], INFINITY);
        fifo.push_back(int32_t(j));
      } else {
        open.push(w.graded[j], int32_t(j));
      }
    }
  }
  // Label the flooded cells, 8-connected, in index order.
  const double cell_area = g.spacing * g.spacing;
  std::vector<int32_t> todo, members;
  std::vector<uint8_t> seen(n, 0);
  for (size_t s = 0; s < n; ++s) {
    if (seen[s] || w.base[s] || !(w.level[s] > z[s])) continue;
    members.clear();
    todo.assign(1, int32_t(s));
    seen[s] = 1;
    double volume = 0;
    while (!todo.empty()) {
      const int32_t c = todo.back();
      todo.pop_back();
      members.push_back(c);
      volume += (double(w.level[c]) - double(z[c])) * cell_area;
      for (int k = 0; k < 8; ++k) {
        const int64_t j = g.neighbour(c % g.width, c / g.width, k);
        if (j < 0 || seen[j] || w.base[j] || !(w.level[j] > z[j])) continue;
        seen[j] = 1;
        todo.push_back(int32_t(j));
      }
    }
    const double area = double(members.size()) * cell_area;
    if (area < min_lake_area) continue;  // a puddle: rivers pass through it
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
