// A stage of Voss midpoint displacement on the whole grid (see refiner.hpp).
#include <vector>

#include <omp.h>

#include "terrain/refiner.hpp"

namespace ft::detail {

// The square and diamond steps fused row by row: square row j, then the
// diamond points of that centre row, then those of the grid row above it,
// whose square rows are both done. A few rows stay in cache instead of two
// sweeps over the whole grid (at 8193^2 the grid is 268 MB). Every point
// reads exactly the values it reads in the two-sweep order (diamond points
// never read each other), so the output is bit-identical. Additions change
// old points between the steps, so they keep the two sweeps (additions.cpp).
void Refiner::fused_stage(int s, int big, int half, float square_delta, float diamond_delta) {
  const int cells = n_ / big;
  in_bands(cells, 3 * cells + 1, [&](int j0, int j1) {
    const int team = threads_for(size_t(j1 - j0) * size_t(cells) * 3);
#pragma omp parallel num_threads(team)
    {
      std::vector<float> g(size_t(cells) + 5);
      const int parts = omp_get_num_threads(), id = omp_get_thread_num();
      const int b0 = j0 + (j1 - j0) * id / parts, b1 = j0 + (j1 - j0) * (id + 1) / parts;
      for (int j = b0; j < b1; ++j) {
        square_one_row(s, j, big, half, square_delta, g.data());
        diamond_one_row(s, half + j * big, big, half, diamond_delta, g.data());
        if (j > b0) diamond_one_row(s, j * big, big, half, diamond_delta, g.data());
      }
      // The grid row at the start of each part needs the square row of the
      // part before it.
#pragma omp barrier
      if (b0 < b1 && !(b0 == 0 && c_.periodic)) diamond_one_row(s, b0 * big, big, half, diamond_delta, g.data());
    }
  });
  std::vector<float> g(size_t(cells) + 5);
  if (c_.periodic) {
    diamond_one_row(s, 0, big, half, diamond_delta, g.data());  // wraps to the last square row
    wrap_edges();
  } else {
    diamond_one_row(s, n_, big, half, diamond_delta, g.data());
  }
}

}  // namespace ft::detail
