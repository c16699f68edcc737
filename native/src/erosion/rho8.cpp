// SPDX-License-Identifier: GPL-3.0-or-later
// Rho8's random numbers and the maps' flats' (see draw_rho8 and
// draw_cell_uniforms in flow_graph.hpp).
#include <algorithm>

#include "erosion/flow_graph.hpp"

namespace ft::erosion {
namespace {

// The routing's own key: erode() takes a heightfield, not a generator's
// seed; the terrain itself is what varies between runs.
constexpr uint64_t kRho8Seed = 0x52686f38;  // "Rho8"

}  // namespace

void draw_row_uniforms(const D8Grid& g, int32_t origin, uint32_t level, Stream stream, int32_t y, float* row) {
  // Cell (x, y) draws the number of (x - ox, y - oy) wrapped into the grid:
  // row and index of the counter, so a torus shifted across its edges (and
  // its sink with it) draws the same numbers for the same cells.
  const int32_t ox = origin < 0 ? 0 : origin % g.width, oy = origin < 0 ? 0 : origin / g.width;
  const Counter c{uint32_t(y >= oy ? y - oy : y - oy + g.height), level, stream};
  uniform_fill(kRho8Seed, c, 0, size_t(g.width - ox), row + ox);
  if (ox > 0) uniform_fill(kRho8Seed, c, uint64_t(g.width - ox), size_t(ox), row);
}

void draw_uniforms_at(const D8Grid& g, int64_t ox, int64_t oy, uint32_t level, Stream stream, int64_t y, int64_t x0,
                      int32_t count, float* out) {
  const int64_t ry = ((y - oy) % g.height + g.height) % g.height;
  const Counter c{uint32_t(ry), level, stream};
  int64_t rx = ((x0 - ox) % g.width + g.width) % g.width;
  for (int32_t done = 0; done < count;) {  // in runs up to the grid's edge
    const int32_t run = int32_t(std::min<int64_t>(count - done, g.width - rx));
    uniform_fill(kRho8Seed, c, uint64_t(rx), size_t(run), out + done);
    done += run;
    rx = 0;
  }
}

void draw_cell_uniforms(const D8Grid& g, int32_t origin, uint32_t level, Stream stream, std::vector<float>& out) {
  out.resize(g.size());
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < g.height; ++y) draw_row_uniforms(g, origin, level, stream, y, out.data() + int64_t(y) * g.width);
}

void draw_rho8(const D8Grid& g, int32_t origin, uint32_t step, FlowGraph& graph) {
  draw_cell_uniforms(g, origin, step, Stream::kFluvialRouting, graph.random);
}

}  // namespace ft::erosion
