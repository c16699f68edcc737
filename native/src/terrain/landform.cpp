// SPDX-License-Identifier: GPL-3.0-or-later
#include "terrain/landform.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace ft::terrain {
namespace {

// 0 at the edge, 1 well inside: the falloff's weight of a sample at (u, v)
// in [0, 1]^2 of the whole terrain. A smoothstep across the band keeps the
// slope continuous where the band begins and flat at the edge.
double falloff_weight(int falloff, double width, double u, double v) {
  const double a = 2 * u - 1, b = 2 * v - 1;  // -1 .. 1 across the terrain
  const double inside = falloff == FT_FALLOFF_SQUARE ? 1 - std::max(std::fabs(a), std::fabs(b))
                                                     : 1 - std::sqrt(a * a + b * b);
  const double t = std::clamp(inside / width, 0.0, 1.0);
  return t * t * (3 - 2 * t);
}

}  // namespace

bool has_landforms(const ft_terrain_params& p) {
  return p.levelling != 0 || p.height_offset != 0 || p.falloff != FT_FALLOFF_NONE || p.sea != FT_SEA_NONE;
}

double mask_weight(const ft_terrain_params& p, double u, double v) {
  const int64_t mw = p.falloff_mask_width, mh = p.falloff_mask_height;
  const double fx = u * double(mw - 1), fy = v * double(mh - 1);
  const int64_t x0 = std::min(int64_t(fx), mw - 2), y0 = std::min(int64_t(fy), mh - 2);
  const double tx = fx - double(x0), ty = fy - double(y0);
  const float* r0 = p.falloff_mask + y0 * mw + x0;
  const float* r1 = r0 + mw;
  const double top = (1 - tx) * r0[0] + tx * r0[1], bottom = (1 - tx) * r1[0] + tx * r1[1];
  return (1 - ty) * top + ty * bottom;
}

namespace {

void validate_mask(const ft_terrain_params& p) {
  if (p.falloff_mask == nullptr)
    invalid("falloff 'custom' needs a mask (falloff_mask, falloff_mask_width x falloff_mask_height values in "
            "[0, 1]; fracterra terrain --falloff-mask FILE); got none");
  for (const auto& [name, side] : {std::pair{"falloff_mask_width", p.falloff_mask_width},
                                   std::pair{"falloff_mask_height", p.falloff_mask_height}})
    if (side < 2 || side > kMaxMaskSide)
      invalid(std::string(name) + " must be in 2.." + std::to_string(kMaxMaskSide) + " (bilinear resampling needs "
              "two samples a side), got " + std::to_string(side));
  const size_t n = size_t(p.falloff_mask_width) * size_t(p.falloff_mask_height);
  for (size_t i = 0; i < n; ++i) {
    const float m = p.falloff_mask[i];
    if (!(m >= 0.0f && m <= 1.0f))  // NaN fails both
      invalid("the falloff mask's values must be in [0, 1] (1 keeps the height, 0 gives the edge level); "
              "sample " + std::to_string(i % size_t(p.falloff_mask_width)) + ", " +
              std::to_string(i / size_t(p.falloff_mask_width)) + " is " + std::to_string(m) +
              " (normalise an image to 0..1)");
  }
}

}  // namespace

void validate_landforms(const ft_terrain_params& p, bool whole) {
  if (p.falloff == FT_FALLOFF_CUSTOM) validate_mask(p);
  if (!whole && p.sea == FT_SEA_FRACTION)
    invalid("sea 'fraction' puts the sea at a quantile of the whole terrain's heights, which a window does not "
            "hold; give the sea as a height (sea 'height', sea_level) for windows, e.g. the level that "
            "ft_terrain_generate reports for a smaller whole terrain");
}

void apply_landforms(const ft_terrain_params& p, const Corners& c, const Placement& at, Heightfield& hf,
                     int threads) {
  if (p.levelling == 0 && p.height_offset == 0 && p.falloff == FT_FALLOFF_NONE) return;
  const double sx = at.whole_width > 1 ? 1.0 / double(at.whole_width - 1) : 0.0;
  const double sy = at.whole_height > 1 ? 1.0 / double(at.whole_height - 1) : 0.0;
  const int w = hf.width(), h = hf.height();
#pragma omp parallel for num_threads(resolve_threads(threads)) schedule(static)
  for (int j = 0; j < h; ++j) {
    // Positions in the whole terrain: the same numbers for a window as for the whole.
    const double v = double(at.y0 + int64_t(j) * at.step) * sy;
    float* row = hf.data() + size_t(j) * size_t(w);
    for (int i = 0; i < w; ++i) {
      const double u = double(at.x0 + int64_t(i) * at.step) * sx;
      double z = row[i];
      if (p.levelling != 0) {
        const double plane = (1 - v) * ((1 - u) * c.c00 + u * c.c10) + v * ((1 - u) * c.c01 + u * c.c11);
        z -= p.levelling * plane;
      }
      z += p.height_offset;
      if (p.falloff != FT_FALLOFF_NONE) {
        // Outside the band (weight 1) the height stays exactly as it was.
        const double m = p.falloff == FT_FALLOFF_CUSTOM ? mask_weight(p, u, v)
                                                        : falloff_weight(p.falloff, p.falloff_width, u, v);
        if (m < 1) z = p.edge_level + m * (z - p.edge_level);
      }
      row[i] = float(z);
    }
  }
}

double apply_sea(const ft_terrain_params& p, Heightfield& hf) {
  if (p.sea == FT_SEA_NONE || hf.size() == 0) return std::numeric_limits<double>::quiet_NaN();
  float level = float(p.sea_level);
  if (p.sea == FT_SEA_FRACTION) {
    // The sample with sea_fraction of the samples below it (the convention
    // of `fracterra scene --sea-fraction`): fraction 0 is the lowest sample,
    // so nothing changes.
    std::vector<float> z(hf.data(), hf.data() + hf.size());
    const size_t k = std::min(z.size() - 1, size_t(p.sea_fraction * double(z.size())));
    std::nth_element(z.begin(), z.begin() + std::ptrdiff_t(k), z.end());
    level = z[k];
  }
  float* d = hf.data();
  const size_t n = hf.size();
  for (size_t i = 0; i < n; ++i) d[i] = std::max(d[i], level);
  return double(level);
}

}  // namespace ft::terrain
