// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/clouds.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace ft::analysis {

GrayImage clouds_image(const Heightfield& hf, const CloudOptions& o) {
  if (o.bit_depth != 8 && o.bit_depth != 16) invalid("bit depth must be 8 or 16, got " + std::to_string(o.bit_depth));
  if (hf.size() == 0) invalid("the heightfield is empty");
  const float* z = hf.data();
  for (size_t i = 0; i < hf.size(); ++i)
    if (!std::isfinite(z[i])) invalid("heightfield sample " + std::to_string(i) + " is " + format_number(z[i]) +
                                      "; clouds need finite samples");
  const double threshold = resolve_level(hf, o.threshold);
  const HeightStats s = hf.stats();
  const double range = s.max - s.min;
  const double e_t = std::max(threshold - s.min, 1e-3 * range);
  const double e_max = range;
  const double full = o.bit_depth == 16 ? 65535.0 : 255.0;
  // log(e_max / e_T) > 0 whenever some sample is above the threshold.
  const double scale = e_max > e_t ? full / std::log(e_max / e_t) : 0.0;
  GrayImage img;
  img.width = hf.width();
  img.height = hf.height();
  img.bit_depth = o.bit_depth;
  img.pixels.resize(hf.size());
#pragma omp parallel for schedule(static)
  for (size_t i = 0; i < hf.size(); ++i) {
    const double e = double(z[i]) - s.min;
    img.pixels[i] = z[i] > threshold && e > e_t
                        ? uint16_t(std::clamp(std::lround(std::log(e / e_t) * scale), 0L, long(full)))
                        : uint16_t(0);
  }
  img.text["Software"] = "fracterra";
  img.text["fracterra:clouds-threshold"] = format_number(threshold);
  return img;
}

}  // namespace ft::analysis
