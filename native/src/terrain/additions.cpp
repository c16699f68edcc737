// SPDX-License-Identifier: GPL-3.0-or-later
// A stage of Feder's successive random additions on the whole grid (see
// refiner.hpp): after each half-step, delta g is added to the points of the
// grid as it stands, so the steps run as two sweeps.
#include <vector>

#include "terrain/refiner.hpp"

namespace ft::terrain::detail {

void Refiner::additions_stage(int s, int big, int half, float square_delta, float diamond_delta) {
  square_step(s, big, half, square_delta);
  add_to_grid(s, 0, big, square_delta, Stream::kTerrainAddOld);
  diamond_step(s, big, half, diamond_delta);
  add_to_grid(s, 0, big, diamond_delta, Stream::kTerrainAddNew);
  add_to_grid(s, half, big, diamond_delta, Stream::kTerrainAddHalf);
}

// Square step: centres of the squares of side `big`.
void Refiner::square_step(int s, int big, int half, float delta) {
  const int cells = n_ / big;
  in_bands(cells, cells, [&](int j0, int j1) {
#pragma omp parallel num_threads(threads_for(size_t(j1 - j0) * size_t(cells)))
    {
      std::vector<float> g(size_t(cells) + 4);
#pragma omp for schedule(static)
      for (int j = j0; j < j1; ++j) square_one_row(s, j, big, half, delta, g.data());
    }
  });
}

// Diamond step: the edge midpoints, from their 4 axis neighbours (3 on a
// border, or wrapped around when periodic).
void Refiner::diamond_step(int s, int big, int half, float delta) {
  const int cells = n_ / big;
  const int rows = 2 * cells + 1;
  in_bands(rows, cells + 1, [&](int r0, int r1) {
#pragma omp parallel num_threads(threads_for(size_t(r1 - r0) * size_t(cells)))
    {
      std::vector<float> g(size_t(cells) + 5);
#pragma omp for schedule(static)
      for (int r = r0; r < r1; ++r) {
        const int y = r * half;
        if (c_.periodic && y == n_) continue;  // copied from row 0 below
        diamond_one_row(s, y, big, half, delta, g.data());
      }
    }
  });
  if (c_.periodic) wrap_edges();
}

// Every point of the grid with spacing `step` starting at `origin` gets
// delta g (reference nodes stay as given). Row j of that grid draws from row
// j of the stage's counter (columns likewise): the place in the stage's own
// grid, the same at any levels.
void Refiner::add_to_grid(int level, int origin, int step, float delta, Stream stream) {
  const int count = addition_count(origin, step);
  in_bands(count, count, [&](int j0, int j1) {
#pragma omp parallel num_threads(threads_for(size_t(j1 - j0) * size_t(count)))
    {
      std::vector<float> g(size_t(count) + 4);
#pragma omp for schedule(static)
      for (int j = j0; j < j1; ++j) {
        const int y = origin + j * step;
        gaussian_fill(c_.seed, Counter{uint32_t(j), uint32_t(level), stream}, 0, count, g.data());
        float* r = row(y);
        for (int i = 0; i < count; ++i) {
          const int x = origin + i * step;
          if (!pinned(x, y)) r[x] += delta * g[i];
        }
      }
    }
  });
  if (c_.periodic) wrap_edges();
}

}  // namespace ft::terrain::detail
