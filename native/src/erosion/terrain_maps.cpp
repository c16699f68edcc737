// SPDX-License-Identifier: GPL-3.0-or-later
// The maps of an eroded terrain: drainage area by multiple flow over the
// filled surface (its flats graded, flat_resolution.hpp), slope and
// curvature by central differences on the D8 grid, and the depths eroded
// and deposited.
#include <algorithm>
#include <cmath>

#include "core/buffer.hpp"
#include "erosion/block_drainage.hpp"
#include "erosion/erosion.hpp"
#include "erosion/flat_resolution.hpp"
#include "erosion/flow_graph.hpp"
#include "erosion/multiple_flow.hpp"

namespace ft::erosion {
namespace {

// The maps' bar, by the parts' times at 4097^2 (Land, 2 cores at load 2-4):
// the fill about 36% of it, the flats' grading 9%, the area 40%, the
// depths, slope and curvature the rest.
constexpr double kSurfaceShare = 0.45, kFillOfSurface = 0.8, kAreaShare = 0.85, kDepthsShare = 0.88;
// Slope and curvature in bands of rows, with a report after each.
constexpr int32_t kSlopeBands = 4;

}  // namespace

void slope_curvature(const D8Grid& g, const float* z, float* slope, float* curvature, const Progress& progress) {
  const double inv = 1.0 / g.spacing;
  for (int32_t band = 0; band < kSlopeBands; ++band) {
    const int32_t y0 = int32_t(int64_t(g.height) * band / kSlopeBands);
    const int32_t y1 = int32_t(int64_t(g.height) * (band + 1) / kSlopeBands);
#pragma omp parallel for schedule(static)
    for (int32_t y = y0; y < y1; ++y)
      for (int32_t x = 0; x < g.width; ++x) {
        const size_t i = size_t(y) * g.width + x;
        // A missing neighbour at a bounded edge mirrors the one opposite, so
        // the differences become one-sided and the Laplacian stays second order.
        double nbr[4];
        for (int p = 0; p < 4; ++p) {
          const int64_t j = g.neighbour(x, y, 2 * p);
          const int64_t o = g.neighbour(x, y, (2 * p + 4) & 7);
          nbr[p] = j >= 0 ? z[j] : (o >= 0 ? 2.0 * z[i] - z[o] : z[i]);
        }
        const double gx = 0.5 * (nbr[0] - nbr[2]) * inv, gy = 0.5 * (nbr[1] - nbr[3]) * inv;
        slope[i] = float(std::sqrt(gx * gx + gy * gy));  // no overflow to guard against: hypot costs
        curvature[i] = float((nbr[0] + nbr[1] + nbr[2] + nbr[3] - 4.0 * z[i]) * inv * inv);
      }
    progress.report(double(band + 1) / kSlopeBands);
  }
}

DrainageSurface drainage_surface(const D8Grid& g, const float* out, const Progress& progress, const FlatFrame* frame) {
  const int64_t cells = int64_t(g.size());
  DrainageSurface s;
  s.z = Buffer<float>(g.size());
  // Heights nearer 0 than half a float step at the terrain's largest are 0
  // here: creep leaves a plain that was exactly 0 (the edge level a falloff
  // reaches) at 1e-36 .. 1e-8, which a float at the terrain's scale cannot
  // tell apart, and the water followed those remnants along straight rows
  // and diagonals. (Only those: rounding every height to the float steps of
  // the largest would change the shares everywhere.) The terrain keeps them.
  float top = 0.0f;
#pragma omp parallel for schedule(static) reduction(max : top)
  for (int64_t i = 0; i < cells; ++i) top = std::max(top, std::fabs(out[i]));
  const float unseen = 0.5f * (std::nextafter(top, INFINITY) - top);
  float* z = s.z.data();
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < cells; ++i) z[i] = std::fabs(out[i]) < unseen ? 0.0f : out[i];
  s.sink = g.periodic ? periodic_sink(g, z) : -1;
  // One fill of the cells that do not drain: route_and_fill's local fills
  // flooded an eroded 4097^2 terrain's hundred thousand pits (its flat lake
  // floors and plain) one by one, 20 M cells raised in all, 4.4 s without a
  // report; fill_closed_basins takes 2.3 s of CPU (a global fill 3.9 s) and
  // reports as it goes. Flat: the grading is resolve_flats'.
  {
    const ProgressPart part(progress, 0.0, kFillOfSurface);
    fill_closed_basins(g, z, s.sink, part.progress(), true);
  }
  const ProgressPart part(progress, kFillOfSurface, 1.0 - kFillOfSurface);
  resolve_flats(g, z, s.sink, s.flats, part.progress(), frame);
  return s;
}

void drainage_area_map(const D8Grid& g, const float* out, float* area_out, const Progress& progress) {
  // The area on the surface as it would drain with its pits filled (a
  // lake's cells all carry what flows through it), by multiple flow
  // directions so the map has no grid-aligned streaks, across flats too.
  DrainageSurface surface;
  {
    const ProgressPart part(progress, 0.0, kSurfaceShare / kAreaShare);
    surface = drainage_surface(g, out, part.progress());
  }
  std::vector<double> area;
  {
    const ProgressPart part(progress, kSurfaceShare / kAreaShare, 1.0 - kSurfaceShare / kAreaShare);
    multiple_flow_area(g, surface.z.data(), surface.sink, area, part.progress(), &surface.flats);
  }
  const int64_t cells = int64_t(g.size());
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < cells; ++i) area_out[i] = float(area[i]);
}

void depth_maps(const float* in, const float* out, const std::vector<float>& lifted, int64_t cells, float* eroded,
                float* deposited) {
  // Against the input plus what the fluvial run lifted it, so uplift never
  // shows as deposit.
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < cells; ++i) {
    const float change = out[i] - (in[i] + (lifted.empty() ? 0.0f : lifted[i]));
    eroded[i] = std::max(0.0f, -change);
    deposited[i] = std::max(0.0f, change);
  }
}

void erosion_maps(const D8Grid& g, const float* in, const float* out, const std::vector<float>& lifted,
                  ErosionMaps& maps, const Progress& progress, const CoarseFlow* coarse) {
  {
    const ProgressPart part(progress, 0.0, kAreaShare);
    if (coarse) block_drainage_area(g, *coarse, out, maps.drainage_area.data(), part.progress());
    else drainage_area_map(g, out, maps.drainage_area.data(), part.progress());
  }
  depth_maps(in, out, lifted, int64_t(g.size()), maps.eroded.data(), maps.deposited.data());
  progress.report(kDepthsShare);
  const ProgressPart part(progress, kDepthsShare, 1.0 - kDepthsShare);
  slope_curvature(g, out, maps.slope.data(), maps.curvature.data(), part.progress());
}

}  // namespace ft::erosion
