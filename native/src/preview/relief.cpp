// SPDX-License-Identifier: GPL-3.0-or-later
#include "preview/relief.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace ft::preview {
namespace {

struct Rgb {
  float r, g, b;
};

// Colour ramp over the normalised altitude t in [0, 1] above the sea.
Rgb land_colour(float t) {
  static const struct {
    float t;
    Rgb c;
  } ramp[] = {{0.00f, {0.82f, 0.76f, 0.55f}},  // sand
              {0.04f, {0.40f, 0.58f, 0.28f}},  // grass
              {0.35f, {0.30f, 0.45f, 0.22f}},  // forest
              {0.60f, {0.50f, 0.44f, 0.36f}},  // rock
              {0.82f, {0.62f, 0.60f, 0.58f}},  // high rock
              {0.92f, {0.95f, 0.95f, 0.97f}},  // snow
              {1.00f, {1.00f, 1.00f, 1.00f}}};
  t = std::clamp(t, 0.0f, 1.0f);
  for (size_t i = 1; i < std::size(ramp); ++i) {
    if (t <= ramp[i].t) {
      const float u = (t - ramp[i - 1].t) / (ramp[i].t - ramp[i - 1].t);
      const Rgb& a = ramp[i - 1].c;
      const Rgb& b = ramp[i].c;
      return {a.r + u * (b.r - a.r), a.g + u * (b.g - a.g), a.b + u * (b.b - a.b)};
    }
  }
  return ramp[std::size(ramp) - 1].c;
}

uint8_t to_byte(float v) { return uint8_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

std::vector<uint8_t> shaded_relief(const Heightfield& hf, const ReliefOptions& o) {
  check_range("sea_fraction", o.sea_fraction, 0.0, 1.0);
  check_range("sun_elevation", o.sun_elevation, 0.0, 90.0);
  check_finite("sun_azimuth", o.sun_azimuth);
  check_range("exaggeration", o.exaggeration, 0.0, 1e6);
  const int w = hf.width(), h = hf.height();
  const HeightStats s = hf.stats();
  if (!std::isfinite(s.min) || !std::isfinite(s.max)) invalid("the heightfield holds NaN or infinite samples");
  const double range = s.max > s.min ? s.max - s.min : 1.0;
  const double sea = s.min + o.sea_fraction * range;
  // Slope scale: with exaggeration 0 the RMS slope per pixel is set to 0.6,
  // which shades every resolution and H alike; otherwise heights are in
  // units of the terrain's width (width spans 1) times the exaggeration.
  double k;
  if (o.exaggeration > 0) {
    k = o.exaggeration * (w - 1);
  } else {
    double sum = 0;
    size_t n = 0;
    for (int y = 0; y < h; y += 4)
      for (int x = 0; x + 1 < w; x += 4) {
        const double d = hf.at(x + 1, y) - hf.at(x, y);
        sum += d * d, ++n;
      }
    const double rms = n ? std::sqrt(sum / double(n)) : 0.0;
    k = rms > 0 ? 0.6 / rms : 1.0;
  }
  const double az = o.sun_azimuth * M_PI / 180.0, alt = o.sun_elevation * M_PI / 180.0;
  // Light direction in image coordinates (x right, y down, z up).
  const double lx = std::sin(az) * std::cos(alt), ly = -std::cos(az) * std::cos(alt), lz = std::sin(alt);
  std::vector<uint8_t> rgb(size_t(w) * h * 3);
#pragma omp parallel for schedule(static)
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int x0 = std::max(x - 1, 0), x1 = std::min(x + 1, w - 1);
      const int y0 = std::max(y - 1, 0), y1 = std::min(y + 1, h - 1);
      const double dzdx = (hf.at(x1, y) - hf.at(x0, y)) * k / std::max(x1 - x0, 1);
      const double dzdy = (hf.at(x, y1) - hf.at(x, y0)) * k / std::max(y1 - y0, 1);
      const double nx = -dzdx, ny = -dzdy, nz = 1.0;
      const double shade = std::max(0.0, (nx * lx + ny * ly + nz * lz) / std::sqrt(nx * nx + ny * ny + 1.0));
      const double z = hf.at(x, y);
      Rgb c;
      float light;
      if (z < sea) {
        const float depth = float((sea - z) / (sea - s.min + 1e-12));
        c = {0.16f - 0.10f * depth, 0.38f - 0.18f * depth, 0.62f - 0.22f * depth};
        light = 1.0f;
      } else {
        c = land_colour(float((z - sea) / (s.max - sea + 1e-12)));
        light = float(0.25 + 0.85 * shade);
      }
      uint8_t* px = rgb.data() + (size_t(y) * w + x) * 3;
      px[0] = to_byte(c.r * light);
      px[1] = to_byte(c.g * light);
      px[2] = to_byte(c.b * light);
    }
  }
  return rgb;
}

}  // namespace ft::preview
