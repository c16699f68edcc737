// SPDX-License-Identifier: GPL-3.0-or-later
#include "splat/splat_map.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "core/error.hpp"
#include "core/parallel_rows.hpp"
#include "splat/splat_params.hpp"

namespace ft::splat {
namespace {

constexpr double kPi = 3.14159265358979323846;

double rise(double x, double edge, double blend) {
  if (blend <= 0) return x >= edge ? 1.0 : 0.0;
  return std::clamp((x - edge) / blend + 0.5, 0.0, 1.0);
}

void check_map(const char* what, const Heightfield* map, const Heightfield& terrain) {
  if (map && (map->width() != terrain.width() || map->height() != terrain.height()))
    invalid(std::string("splat: the ") + what + " map is " + std::to_string(map->width()) + " x " +
            std::to_string(map->height()) + "; it must be the terrain's size, " + std::to_string(terrain.width()) +
            " x " + std::to_string(terrain.height()));
}

// Slope in degrees at (x, y): central differences inside, one-sided at the edges.
double slope_degrees(const Heightfield& hf, int32_t x, int32_t y, double spacing) {
  const int32_t x0 = std::max(x - 1, 0), x1 = std::min(x + 1, hf.width() - 1);
  const int32_t y0 = std::max(y - 1, 0), y1 = std::min(y + 1, hf.height() - 1);
  const double gx = x1 > x0 ? (double(hf.at(x1, y)) - hf.at(x0, y)) / ((x1 - x0) * spacing) : 0.0;
  const double gy = y1 > y0 ? (double(hf.at(x, y1)) - hf.at(x, y0)) / ((y1 - y0) * spacing) : 0.0;
  return std::atan(std::hypot(gx, gy)) * 180.0 / kPi;
}

}  // namespace

std::vector<ft_splat_params> default_layers() {
  ft_splat_params base = defaults_of<ft_splat_params>(splat_param_table());
  // The first layer is the ground where no other rule holds: grass below
  // the snow line.
  ft_splat_params grass = base, rock = base, sediment = base, snow = base;
  grass.name = "grass";
  grass.height_max = 0.72, grass.height_blend = 0.1, grass.weight = 1;
  grass.color[0] = 0.30, grass.color[1] = 0.42, grass.color[2] = 0.18;
  // Rock where it is too steep for soil to stay (soil's angle of repose,
  // about 30-35 degrees).
  rock.name = "rock";
  rock.slope_min = 33, rock.slope_blend = 12, rock.weight = 3;
  rock.color[0] = 0.46, rock.color[1] = 0.43, rock.color[2] = 0.40;
  // Sediment where erosion laid material down or where water gathers.
  sediment.name = "sediment";
  sediment.deposit_min = 0.002, sediment.deposit_blend = 0.002;
  sediment.flow_min = 0.002, sediment.flow_blend = 1;
  sediment.slope_max = 30, sediment.slope_blend = 10, sediment.weight = 2;
  sediment.color[0] = 0.62, sediment.color[1] = 0.55, sediment.color[2] = 0.42;
  // Snow high up, sliding off the steepest faces.
  snow.name = "snow";
  snow.height_min = 0.75, snow.height_blend = 0.08, snow.slope_max = 40, snow.slope_blend = 10, snow.weight = 4;
  snow.color[0] = 0.93, snow.color[1] = 0.94, snow.color[2] = 0.96;
  return {grass, rock, sediment, snow};
}

double band(double x, double lo, double hi, double blend) {
  return rise(x, lo, blend) * rise(-x, -hi, blend);
}

namespace {

// What every sample's rules read, checked and worked out once.
struct Rules {
  const SplatInputs& in;
  std::vector<ft_splat_params> layers;
  std::vector<double> log_flow_min;  // per layer: log10 of its flow_min (a log per sample was 5% of the time)
  double low = 0, range = 0;  // the terrain's lowest height and its relief
  double spacing = 1, area = 1;
};

Rules rules_of(const SplatInputs& in, const ft_splat_params* given, int32_t n) {
  check_not_null("terrain", in.terrain);
  validate_layers(given, n);
  const Heightfield& hf = *in.terrain;
  check_map("deposited", in.deposited, hf);
  check_map("drainage_area", in.drainage_area, hf);
  Rules r{in, std::vector<ft_splat_params>(static_cast<size_t>(n)), {}};
  for (int32_t k = 0; k < n; ++k) {
    r.layers[size_t(k)] = upgraded(splat_param_table(), given[k]);
    r.log_flow_min.push_back(std::log10(r.layers[size_t(k)].flow_min));
  }
  const HeightStats s = hf.stats();
  r.low = s.min, r.range = s.max - s.min;
  r.spacing = hf.world_size() > 0 && hf.width() > 1 ? hf.world_size() / (hf.width() - 1) : 1.0;
  r.area = r.spacing * r.spacing * double(hf.width() - 1) * double(std::max(hf.height() - 1, 1));
  if (in.frame) r.low = in.frame->low, r.range = in.frame->range, r.area = in.frame->area;
  return r;
}

// The layers' fractions of the samples of row y: width * n floats.
void row_fractions(const Rules& r, int32_t y, float* out) {
  const Heightfield& hf = *r.in.terrain;
  const int32_t w = hf.width(), n = int32_t(r.layers.size());
  double wk[kMaxLayers];
  for (int32_t x = 0; x < w; ++x) {
    const size_t i = size_t(y) * size_t(w) + size_t(x);
    const double height = r.range > 0 ? (hf.at(x, y) - r.low) / r.range : 0.0;
    const double slope = slope_degrees(hf, x, y, r.spacing);
    const double deposit = r.in.deposited && r.range > 0 ? r.in.deposited->data()[i] / r.range : 0.0;
    // Flow compared on a log scale: drainage areas span cells to the whole map.
    const double flow =
        r.in.drainage_area ? std::log10(std::max(double(r.in.drainage_area->data()[i]) / r.area, 1e-30)) : -30.0;
    double sum = 0;
    for (int32_t k = 0; k < n; ++k) {
      const ft_splat_params& l = r.layers[size_t(k)];
      double v = l.weight * band(height, l.height_min, l.height_max, l.height_blend) *
                 band(slope, l.slope_min, l.slope_max, l.slope_blend);
      const bool by_deposit = l.deposit_min > 0, by_flow = l.flow_min > 0;
      if (by_deposit || by_flow)
        v *= std::max(by_deposit ? rise(deposit, l.deposit_min, l.deposit_blend) : 0.0,
                      by_flow ? rise(flow, r.log_flow_min[size_t(k)], l.flow_blend) : 0.0);
      wk[k] = v;
      sum += v;
    }
    float* f = out + size_t(x) * size_t(n);
    if (!(sum > 0)) {
      f[0] = 1.0f;
      for (int32_t k = 1; k < n; ++k) f[k] = 0.0f;
    } else {
      for (int32_t k = 0; k < n; ++k) f[k] = float(wk[k] / sum);
    }
  }
}

// The layers' colours mixed by a sample's fractions `f`: sRGB 0..1.
void mix(const Rules& r, const float* f, float* rgb) {
  const int32_t n = int32_t(r.layers.size());
  for (int c = 0; c < 3; ++c) {
    double v = 0;
    for (int32_t k = 0; k < n; ++k) v += double(f[k]) * r.layers[size_t(k)].color[c];
    rgb[c] = float(std::clamp(v, 0.0, 1.0));
  }
}

// IEC 61966-2-1's decoding of an sRGB value 0..1.
float linear_from_srgb(float c) { return float(c <= 0.04045f ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4)); }

}  // namespace

std::vector<float> layer_fractions(const SplatInputs& in, const ft_splat_params* given, int32_t n) {
  const Rules r = rules_of(in, given, n);
  const int32_t w = in.terrain->width(), h = in.terrain->height();
  std::vector<float> out(size_t(w) * size_t(h) * size_t(n));
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < h; ++y) row_fractions(r, y, out.data() + size_t(y) * size_t(w) * size_t(n));
  return out;
}

void round_to_total(const float* f, int32_t n, int32_t total, uint16_t* out) {
  // Floors first, then one more to the largest remainders until the sum is
  // the total. The fractions are renormalised in double so that float
  // rounding of their sum cannot leave the floors above the total.
  double sum = 0;
  for (int32_t k = 0; k < n; ++k) sum += f[k];
  int32_t given = 0;
  double remainder[kMaxLayers];
  for (int32_t k = 0; k < n; ++k) {
    const double exact = sum > 0 ? double(f[k]) / sum * total : (k == 0 ? total : 0);
    const double whole = std::floor(exact);
    out[k] = uint16_t(whole);
    remainder[k] = exact - whole;
    given += int32_t(whole);
  }
  while (given < total) {
    int32_t best = 0;
    for (int32_t k = 1; k < n; ++k)
      if (remainder[k] > remainder[best]) best = k;
    ++out[best];
    remainder[best] = -1;  // each layer gets at most one more
    ++given;
  }
  while (given > total) {  // only if the floors summed past the total: take from the largest
    int32_t best = 0;
    for (int32_t k = 1; k < n; ++k)
      if (out[k] > out[best]) best = k;
    --out[best];
    --given;
  }
}

std::vector<uint16_t> splat_weights(const SplatInputs& in, const ft_splat_params* layers, int32_t n,
                                    int32_t total) {
  if (total != 255 && total != 65535) invalid("splat total must be 255 (8-bit maps) or 65535 (16-bit), got " +
                                              std::to_string(total));
  const std::vector<float> f = layer_fractions(in, layers, n);
  const size_t samples = f.size() / size_t(n);
  std::vector<uint16_t> out(f.size());
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < int64_t(samples); ++i)
    round_to_total(f.data() + size_t(i) * size_t(n), n, total, out.data() + size_t(i) * size_t(n));
  return out;
}

std::vector<float> splat_colors(const SplatInputs& in, const ft_splat_params* given, int32_t n) {
  const Rules r = rules_of(in, given, n);
  const int32_t w = in.terrain->width(), h = in.terrain->height();
  std::vector<float> rgb(size_t(w) * size_t(h) * 3);
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < h; ++y) {
    std::vector<float> f(size_t(w) * size_t(n));
    row_fractions(r, y, f.data());
    for (int32_t x = 0; x < w; ++x)
      mix(r, f.data() + size_t(x) * size_t(n), rgb.data() + (size_t(y) * size_t(w) + size_t(x)) * 3);
  }
  return rgb;
}

std::vector<float> splat_colors_linear(const SplatInputs& in, const ft_splat_params* layers, int32_t n) {
  std::vector<float> rgb = splat_colors(in, layers, n);
  for (float& c : rgb) c = linear_from_srgb(c);
  return rgb;
}

void splat_colors_linear_rgba(const SplatInputs& in, const ft_splat_params* given, int32_t n, int threads,
                              const Progress& progress, float* rgba) {
  const Rules r = rules_of(in, given, n);
  const int32_t w = in.terrain->width();
  for_rows(in.terrain->height(), threads, progress, [&](int64_t y) {
    std::vector<float> f(size_t(w) * size_t(n));
    row_fractions(r, int32_t(y), f.data());
    // The last value each channel decoded: where one layer covers the
    // ground (most of a terrain), neighbours repeat it, and the decoding's
    // pow was the largest part of the time.
    float last_in[3] = {-1.0f, -1.0f, -1.0f}, last_out[3] = {0.0f, 0.0f, 0.0f};
    for (int32_t x = 0; x < w; ++x) {
      float* out = rgba + (size_t(y) * size_t(w) + size_t(x)) * 4;
      mix(r, f.data() + size_t(x) * size_t(n), out);
      for (int c = 0; c < 3; ++c) {
        if (out[c] != last_in[c]) last_in[c] = out[c], last_out[c] = linear_from_srgb(out[c]);
        out[c] = last_out[c];
      }
      out[3] = 1.0f;
    }
  });
}

}  // namespace ft::splat
