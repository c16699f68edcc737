// SPDX-License-Identifier: GPL-3.0-or-later
// The landscape model by windows (see landscape_window.hpp).
//
// The model's run reads the terrain through a subgrid, every `step`-th
// sample (about four to the model's cell, a divisor of the grid's period:
// for midpoint a coarser level of the same terrain), averaged over the
// model's cell: so its input, and its run, cost the same at every size and
// any task can compute them. Each sample of the terrain's grid then takes
// the run's change resampled bilinearly, buried into its texture where it
// is a deposit (the texture's spread over a model cell measured on the
// subgrid), and the detail run (detail_run.hpp), whose every sample reads a
// bounded neighbourhood. A window is computed on itself grown by that reach.
#include "erosion/landscape_window.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/buffer.hpp"
#include "core/error.hpp"
#include "erosion/detail_run.hpp"
#include "erosion/flow_graph.hpp"
#include "erosion/landscape_parts.hpp"
#include "erosion/model_constants.hpp"
#include "erosion/one_cell_pits.hpp"
#include "erosion/sea.hpp"

namespace ft::erosion {
namespace {

int64_t wrap(int64_t v, int64_t n) { return ((v % n) + n) % n; }

// The subgrid's step: the largest divisor of the grid's period (both sides)
// at most a quarter of the model's cell, so the subgrid's samples lie on
// the grid and span it corner to corner.
int32_t subgrid_step(const D8Grid& g, double factor) {
  const int32_t e = g.periodic ? 0 : 1;
  const int32_t period = std::gcd(g.width - e, g.height - e);
  const int32_t most = std::max(1, int32_t(factor / 4));
  int32_t best = 1;
  for (int32_t d = 1; d <= std::min(most, period); ++d)
    if (period % d == 0) best = d;
  return best;
}

// The whole's bands: a band's region (about 72 bytes a sample at the detail
// run's peak: its buffers, the wave's lists, the inputs) holds at most this
// share of the terrain's samples, or this many when that is more.
constexpr double kRegionShare = 0.4;
constexpr int64_t kRegionSamples = int64_t(1) << 23;

// How far a one-cell pit is lifted: the erosion mask where rain falls, 0
// where none does (no water ponds there; null: 1 everywhere).
float pit_lift_weight(double rainfall, float mask, float rain) { return rainfall > 0 && rain > 0 ? mask : 0.0f; }

std::vector<float> pit_lift_weights(const ErosionConfig& c, int32_t w, int32_t h) {
  const std::vector<float> mask = resample_map(c.erosion_mask, w, h), rain = resample_map(c.rain_map, w, h);
  if (mask.empty() && rain.empty() && c.model.rainfall > 0) return {};
  std::vector<float> out(size_t(w) * h);
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = pit_lift_weight(c.model.rainfall, mask.empty() ? 1.0f : mask[i], rain.empty() ? 1.0f : rain[i]);
  return out;
}

// The own grid's one-cell pits lifted, the volume added to the budget's
// `filled_pits` (it comes from no bed: the budget balances with it).
void lift_pits(float* z, int32_t w, int32_t h, bool periodic, const uint8_t* sea, const float* mask, const D8Grid& g,
               MassBudget* budget) {
  std::vector<float> was;
  if (budget) was.assign(z, z + size_t(w) * h);
  lift_one_cell_pits(z, w, h, periodic, sea, mask);
  if (!budget) return;
  double added = 0;
  for (size_t i = 0; i < was.size(); ++i) added += double(z[i]) - was[i];
  budget->filled_pits += added * g.spacing * g.spacing;
}

}  // namespace

std::vector<float> resample_map(const MapInput& m, int32_t width, int32_t height) {
  if (!m.values) return {};
  D8Grid from, to;
  from.width = m.width, from.height = m.height;
  to.width = width, to.height = height;
  std::vector<float> out = resample(m.values, from, to);
  for (float& v : out) v = std::clamp(v, 0.0f, 1.0f);
  return out;
}

void HeightSource::read_subgrid(int32_t step, int32_t w, int32_t h, float* out) const {
  std::vector<float> row;
  const int32_t span = (w - 1) * step + 1;
  row.resize(size_t(span));
  for (int32_t j = 0; j < h; ++j) {
    read(0, int64_t(j) * step, span, 1, row.data());
    for (int32_t i = 0; i < w; ++i) out[size_t(j) * w + i] = row[size_t(i) * step];
  }
}

void ArraySource::read(int64_t x0, int64_t y0, int32_t w, int32_t h, float* out) const {
#pragma omp parallel for schedule(static)
  for (int32_t j = 0; j < h; ++j) {
    const int64_t y = g_.periodic ? wrap(y0 + j, g_.height) : y0 + j;
    const float* row = z_ + size_t(y) * g_.width;
    float* dst = out + size_t(j) * w;
    if (!g_.periodic) {
      std::copy(row + x0, row + x0 + w, dst);
      continue;
    }
    for (int32_t i = 0; i < w; ++i) dst[i] = row[wrap(x0 + i, g_.width)];
  }
}

void ArraySource::read_subgrid(int32_t step, int32_t w, int32_t h, float* out) const {
#pragma omp parallel for schedule(static)
  for (int32_t j = 0; j < h; ++j)
    for (int32_t i = 0; i < w; ++i) out[size_t(j) * w + i] = z_[size_t(j) * step * g_.width + size_t(i) * step];
}

void coarse_input(const D8Grid& g, const HeightSource& src, double sea_level, LandscapeModel& m) {
  const int32_t edge = g.periodic ? 0 : 1;
  const int32_t side = std::max(g.width, g.height) - edge;
  const double factor = double(side) / kModelCells;
  D8Grid& coarse = m.coarse;
  coarse = g;
  coarse.sea = nullptr;
  coarse.width = std::max(3, int32_t(std::lround((g.width - edge) / factor)) + edge);
  coarse.height = std::max(3, int32_t(std::lround((g.height - edge) / factor)) + edge);
  coarse.spacing = g.spacing * double(g.width - edge) / (coarse.width - edge);
  m.step = subgrid_step(g, factor);
  m.radius = int32_t(factor / 2) / m.step;
  D8Grid& sub = m.sub;
  sub = g;
  sub.sea = nullptr;
  sub.width = (g.width - edge) / m.step + edge;
  sub.height = (g.height - edge) / m.step + edge;
  sub.spacing = g.spacing * m.step;
  std::vector<float> z(sub.size());
  src.read_subgrid(m.step, sub.width, sub.height, z.data());
  m.top = *std::max_element(z.begin(), z.end());
  m.before = resample(box_mean(z.data(), sub, m.radius).data(), sub, coarse);
  // The model's sea: its cells whose nearest subgrid sample is sea (their
  // averaged heights mix in the coast, so the level would miss them).
  m.coarse_sea.clear();
  if (!std::isnan(sea_level)) {
    m.coarse_sea.resize(coarse.size());
    const double sx = double(sub.width - edge) / (coarse.width - edge), sy = double(sub.height - edge) / (coarse.height - edge);
    for (int32_t y = 0; y < coarse.height; ++y)
      for (int32_t x = 0; x < coarse.width; ++x) {
        const int32_t fx = std::min(int32_t(std::lround(x * sx)), sub.width - 1);
        const int32_t fy = std::min(int32_t(std::lround(y * sy)), sub.height - 1);
        m.coarse_sea[size_t(y) * coarse.width + x] = in_sea(z[size_t(fy) * sub.width + fx], sea_level);
      }
  }
}

LandscapeModel landscape_model(const D8Grid& g, const HeightSource& src, const ErosionConfig& c, double sea_level,
                               MassBudget* budget, const Progress& progress) {
  LandscapeModel m;
  m.g = g;
  m.g.sea = nullptr;
  m.sea_level = sea_level;
  const double years = c.model.strength * c.model.duration;
  m.erodes = years > 0;
  if (!m.erodes) return m;
  const int32_t edge = g.periodic ? 0 : 1;
  const int32_t side = std::max(g.width, g.height) - edge;
  const bool sea = !std::isnan(sea_level);
  if (side == kModelCells) {
    // One run on the terrain's own grid (the model's): the whole is its
    // only window. A smaller terrain (a preview) runs on the model's grid
    // too, resampled onto it (below): D8 channels are a cell wide, so on
    // its own coarser grid a larger share of it was channel, and a 65^2
    // Rugged Mountains came out 14 % lower than its 1025^2 final.
    m.before.resize(g.size());
    src.read(0, 0, g.width, g.height, m.before.data());
    std::vector<uint8_t> flags;
    D8Grid own = m.g;
    if (sea) {
      flags.resize(g.size());
      for (size_t i = 0; i < g.size(); ++i) flags[i] = in_sea(m.before[i], sea_level);
      own.sea = flags.data();
    }
    m.change = m.before;
    const std::vector<float> mask = resample_map(c.erosion_mask, g.width, g.height);
    const std::vector<float> rain = resample_map(c.rain_map, g.width, g.height);
    model_run(own, c, mask.empty() ? nullptr : mask.data(), rain.empty() ? nullptr : rain.data(), budget, nullptr,
              m.change.data(), years, steps_for(own, c, years, kMaxModelSteps), progress);
    const std::vector<float> lift = pit_lift_weights(c, g.width, g.height);
    lift_pits(m.change.data(), g.width, g.height, g.periodic, flags.empty() ? nullptr : flags.data(),
              lift.empty() ? nullptr : lift.data(), g, budget);
    return m;  // `change` holds the eroded terrain itself
  }
  m.coarse_to_fine = true;
  const double factor = double(side) / kModelCells;
  coarse_input(g, src, sea_level, m);
  progress.report(0.05);
  const D8Grid& coarse = m.coarse;
  const std::vector<uint8_t>& coarse_sea = m.coarse_sea;
  D8Grid run_grid = coarse;
  run_grid.sea = sea ? coarse_sea.data() : nullptr;
  const std::vector<float> coarse_mask = resample_map(c.erosion_mask, coarse.width, coarse.height);
  const std::vector<float> coarse_rain = resample_map(c.rain_map, coarse.width, coarse.height);
  m.crept.assign(coarse_mask.empty() ? 0 : coarse.size(), 0.0f);
  std::vector<float> after = m.before;
  {
    const ProgressPart part(progress, 0.05, 0.95);
    model_run(run_grid, c, coarse_mask.empty() ? nullptr : coarse_mask.data(),
              coarse_rain.empty() ? nullptr : coarse_rain.data(), budget, m.crept.empty() ? nullptr : m.crept.data(),
              after.data(), years, steps_for(coarse, c, years, kMaxModelSteps), part.progress());
  }
  m.change.resize(after.size());
  for (size_t i = 0; i < after.size(); ++i) m.change[i] = after[i] - m.before[i];
  // A terrain coarser than the model's grid has no detail below its cell:
  // it takes the model's change at its samples and no detail run.
  m.detail_years = factor > 1 ? years * g.spacing / coarse.spacing : 0.0;
  m.detail_steps = steps_for(g, c, m.detail_years, kMaxDetailSteps);
  // One more: a window's one-cell pits are lifted from its neighbours' heights.
  m.reach = detail_reach(g, c, m.detail_years, m.detail_steps) + 1;
  if (g.periodic) {
    // Rho8's numbers keyed from the model's sink, on the terrain's grid.
    const int32_t s = periodic_sink(coarse, m.before.data());
    m.origin_x = std::lround((s % coarse.width) * double(g.width) / coarse.width);
    m.origin_y = std::lround((s / coarse.width) * double(g.height) / coarse.height);
  }
  return m;
}

void landscape_window(const LandscapeModel& m, const HeightSource& src, const ErosionConfig& c, int64_t x0, int64_t y0,
                      int32_t w, int32_t h, float* out, const Progress& progress) {
  const D8Grid& g = m.g;
  if (!m.erodes) {
    src.read(x0, y0, w, h, out);
    return;
  }
  if (!m.coarse_to_fine) {
    ArraySource(g, m.change.data()).read(x0, y0, w, h, out);
    return;
  }
  // The region: the window grown by the detail run's reach (inside a
  // bounded grid), and the input grown further by the texture's spread.
  const int64_t reach = m.reach;
  auto grown = [&](int64_t lo, int64_t len, int64_t by, int64_t n, int64_t& first, int32_t& count) {
    int64_t a = lo - by, b = lo + len + by;
    if (!g.periodic) a = std::max<int64_t>(a, 0), b = std::min<int64_t>(b, n);
    first = a, count = int32_t(b - a);
  };
  Region r;
  r.whole = g;
  grown(x0, w, reach, g.width, r.x0, r.width);
  grown(y0, h, reach, g.height, r.y0, r.height);
  const int32_t s = m.step, edge = g.periodic ? 0 : 1, rad = m.radius;
  // The input: the region grown by what the texture's spread reads (the
  // subgrid's samples of the box means around the subgrid cells it spans).
  const int64_t spread_reach = int64_t(rad + 3) * s;
  int64_t ix0, iy0;
  int32_t iw, ih;
  grown(r.x0, r.width, spread_reach, g.width, ix0, iw);
  grown(r.y0, r.height, spread_reach, g.height, iy0, ih);
  // (Buffers, not vectors: the region's grids are written before they are
  // read, and zero-filling them took one thread a tenth of a 2049^2 run.)
  Buffer<float> input(size_t(iw) * ih);
  src.read(ix0, iy0, iw, ih, input.data());
  auto input_at = [&](int64_t ux, int64_t uy) { return input[size_t(uy - iy0) * iw + size_t(ux - ix0)]; };
  const size_t n = r.size();
  Buffer<float> z(n);
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < r.height; ++y)
    for (int32_t x = 0; x < r.width; ++x) z[size_t(y) * r.width + x] = input_at(r.x0 + x, r.y0 + y);
  // The texture's spread about the model's surface, on the subgrid's
  // samples around the region, then bilinearly at each sample.
  const D8Grid& sub = m.sub;
  const double to_coarse_x = double(m.coarse.width - edge) / (g.width - edge);
  const double to_coarse_y = double(m.coarse.height - edge) / (g.height - edge);
  auto floor_div = [](int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); };
  // Subgrid samples [sx0, sx0 + sw) x [sy0, sy0 + sh) (unwrapped) cover the region.
  const int64_t sx0 = floor_div(r.x0, s) - 1, sy0 = floor_div(r.y0, s) - 1;
  const int32_t sw = int32_t(floor_div(r.x0 + r.width - 1, s) + 2 - sx0 + 1);
  const int32_t sh = int32_t(floor_div(r.y0 + r.height - 1, s) + 2 - sy0 + 1);
  // A subgrid index clamped (bounded) or kept unwrapped (periodic: the
  // input's positions run past the edges as the region's do), in samples.
  auto sub_position = [&](int64_t k, int32_t count) {
    return (g.periodic ? k : std::clamp<int64_t>(k, 0, count - 1)) * s;
  };
  // (z - seen)^2 on the subgrid samples the box means read: the patch grown by rad.
  const int32_t pw = sw + 2 * rad, ph = sh + 2 * rad;
  std::vector<float> sq(size_t(pw) * ph), rows(size_t(pw) * ph), spread(size_t(sw) * sh);
#pragma omp parallel for schedule(static)
  for (int32_t j = 0; j < ph; ++j) {
    const int64_t uy = sub_position(sy0 - rad + j, sub.height);
    for (int32_t i = 0; i < pw; ++i) {
      const int64_t ux = sub_position(sx0 - rad + i, sub.width);
      const double seen = bilinear(m.before.data(), m.coarse.width, m.coarse.height, wrap(ux, g.width) * to_coarse_x,
                                   wrap(uy, g.height) * to_coarse_y, g.periodic);
      const double d = double(input_at(ux, uy)) - seen;
      sq[size_t(j) * pw + i] = float(d * d);
    }
  }
  // The box means in a fixed order (along rows, then columns), in double.
#pragma omp parallel for schedule(static)
  for (int32_t j = 0; j < ph; ++j)
    for (int32_t i = rad; i < pw - rad; ++i) {
      double sum = 0;
      for (int32_t d = -rad; d <= rad; ++d) sum += sq[size_t(j) * pw + i + d];
      rows[size_t(j) * pw + i] = float(sum);
    }
  const double inv = 1.0 / (double(2 * rad + 1) * (2 * rad + 1));
#pragma omp parallel for schedule(static)
  for (int32_t j = 0; j < sh; ++j)
    for (int32_t i = 0; i < sw; ++i) {
      double sum = 0;
      for (int32_t d = -rad; d <= rad; ++d) sum += rows[size_t(j + rad + d) * pw + i + rad];
      spread[size_t(j) * sw + i] = float(sum * inv);
    }
  input = Buffer<float>();
  progress.report(0.1);
  // Each sample: the model's change, buried into its texture where it is a
  // deposit; the mask, rain and sea for the detail run.
  Buffer<float> mask(c.erosion_mask.values ? n : 0), rain(c.rain_map.values ? n : 0);
  Buffer<uint8_t> sea(std::isnan(m.sea_level) ? 0 : n);
  auto map_at = [&](const MapInput& map, int64_t gx, int64_t gy) {
    const double mx = double(map.width - 1) / (g.width - 1), my = double(map.height - 1) / (g.height - 1);
    return std::clamp(bilinear(map.values, map.width, map.height, gx * mx, gy * my, false), 0.0f, 1.0f);
  };
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < r.height; ++y) {
    const int64_t gy = r.row(y);
    for (int32_t x = 0; x < r.width; ++x) {
      const int64_t gx = r.column(x);
      const size_t i = size_t(y) * r.width + x;
      if (!mask.empty()) mask[i] = map_at(c.erosion_mask, gx, gy);
      if (!rain.empty()) rain[i] = map_at(c.rain_map, gx, gy);
      if (!sea.empty()) {
        sea[i] = in_sea(z[i], m.sea_level);
        if (sea[i]) continue;
      }
      const double cx = gx * to_coarse_x, cy = gy * to_coarse_y;
      float d = bilinear(m.change.data(), m.coarse.width, m.coarse.height, cx, cy, g.periodic);
      if (!mask.empty()) {
        // The resampled change blurs across the mask's edge: creep and what
        // lowers are scaled by the terrain's own mask (landscape.cpp).
        const float crept = bilinear(m.crept.data(), m.coarse.width, m.coarse.height, cx, cy, g.periodic);
        const float rest = d - crept;
        d = mask[i] * crept + (rest < 0 ? mask[i] * rest : rest);
      }
      const float seen = bilinear(m.before.data(), m.coarse.width, m.coarse.height, cx, cy, g.periodic);
      // Position of the sample in the spread's patch (subgrid units).
      const int64_t ux = r.x0 + x, uy = r.y0 + y;
      const double px = double(ux) / s - double(sx0), py = double(uy) / s - double(sy0);
      const double sd = std::sqrt(std::max(0.0f, bilinear(spread.data(), sw, sh, px, py, false)));
      // Never lifted above the subgrid's highest (nor clipped below where it stands).
      z[i] = d > 0 ? std::min(std::max(m.top, z[i]), bury(z[i], seen, sd, d, mask.empty() ? 1.0f : mask[i])) : z[i] + d;
    }
  }
  progress.report(0.15);
  DetailInputs in;
  in.mask = mask.empty() ? nullptr : mask.data();
  in.rain = rain.empty() ? nullptr : rain.data();
  in.sea = sea.empty() ? nullptr : sea.data();
  in.origin_x = m.origin_x, in.origin_y = m.origin_y;
  {
    const ProgressPart part(progress, 0.15, 0.85);
    detail_run(r, c, m.detail_years, m.detail_steps, in, z.data(), part.progress());
  }
  const int64_t ox = x0 - r.x0, oy = y0 - r.y0;
  // The window's one-cell pits lifted (one_cell_pits.hpp), from the region's
  // heights around each: every window has the bits of the whole.
#pragma omp parallel for schedule(static)
  for (int32_t j = 0; j < h; ++j)
    for (int32_t i = 0; i < w; ++i) {
      const int32_t x = int32_t(ox) + i, y = int32_t(oy) + j;
      const size_t k = size_t(y) * r.width + x;
      float lifted = z[k];
      if (!r.on_whole_edge(x, y) && (sea.empty() || !sea[k])) {
        float nb[8];
        int q = 0;
        for (int32_t dy = -1; dy <= 1; ++dy)
          for (int32_t dx = -1; dx <= 1; ++dx)
            if (dx || dy) nb[q++] = z[size_t(y + dy) * r.width + x + dx];
        lifted = one_cell_pit_lifted(
            z[k], nb, pit_lift_weight(c.model.rainfall, mask.empty() ? 1.0f : mask[k], rain.empty() ? 1.0f : rain[k]));
      }
      out[size_t(j) * w + i] = lifted;
    }
}

void landscape(const D8Grid& g, const float* in, float* out, const ErosionConfig& c, double sea_level, MassBudget* budget,
               const Progress& progress, LandscapeModel* model) {
  const ArraySource src(g, in);
  const ProgressPart model_part(progress, 0.0, 0.3);
  LandscapeModel m = landscape_model(g, src, c, sea_level, budget, model_part.progress());
  // Bands of whole rows, each computed on itself grown by the reach, small
  // enough that a band's buffers take at most 72 bytes x
  // kRegionShare of the terrain's samples: the bits are the same for any cut.
  const int64_t most = std::max<int64_t>(kRegionSamples, int64_t(kRegionShare * double(g.size())));
  const int64_t rows = std::max<int64_t>(64, most / g.width - 2 * int64_t(m.reach));
  const int32_t bands = m.coarse_to_fine ? int32_t((g.height + rows - 1) / rows) : 1;
  for (int32_t b = 0; b < bands; ++b) {
    const int32_t y0 = int32_t(int64_t(g.height) * b / bands), y1 = int32_t(int64_t(g.height) * (b + 1) / bands);
    const ProgressPart part(progress, 0.3 + 0.7 * b / bands, 0.7 / bands);
    landscape_window(m, src, c, 0, y0, g.width, y1 - y0, out + size_t(y0) * g.width, part.progress());
  }
  if (model) *model = std::move(m);
}

}  // namespace ft::erosion
