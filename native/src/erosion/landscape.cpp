// SPDX-License-Identifier: GPL-3.0-or-later
// The landscape model: channels, talus and fans in world units and years.
//
// Each implicit time step, on a flow graph routed over the surface and
// drained out of its depressions by the basin graph (basin_graph.hpp: the
// lakes themselves stay, to be filled by sediment):
//   detachment  the stream-power law dz/dt = -K Q^m S (n = 1), Q = rainfall x
//               rain map x upstream area, solved implicitly along the stack
//               (Braun & Willett 2013): unconditionally stable;
//   talus       no cell stands steeper than the talus angle above its
//               receiver (one pass along the stack, receivers first);
//   deposition  what was detached and shed flows down the stack, donors
//               first; each cell lays down G x its own rain area / Q of what
//               passes (the deposition term G Qs / Q of Yuan et al. 2019,
//               "A new efficient method to solve the stream power law model
//               taking into account sediment deposition", as fastscapelib's
//               erosion-deposition law), and a deposit never rises above
//               the cell it came from (less a fan slope): fans and valley
//               fills, never a spike; a lake settles G of what it gets,
//               up to its spill level, as a flat floor from its lowest cell
//               up (lake_fill.hpp); what reaches a base level (a bounded
//               grid's edge, a periodic grid's sink, the sea) is carried out;
//   diffusion   hillslope creep D laplacian(z), implicit; the sea floor
//               stays as it is.
// The erosion mask scales detachment, talus and each edge's creep flux (so
// creep moves material only where the mask lets it, and makes or loses
// none); the deposit goes wherever the sediment flows.
//
// Resolution: D8 channels are one cell wide, so the incision of a grid of any
// size depends on its cell size. The model therefore runs at one cell size,
// width / kModelCells, for the whole duration, on the terrain averaged over
// its cells; a finer terrain gets that run's change resampled bilinearly
// onto its own detail, then a short run on its own grid (for the same share
// of the duration as its cell is of the model's) that wears channels into
// the detail, its creep rounding what that run cuts but not the detail
// itself (the rock's texture, below the model's cell). A preview and a
// final then share their landform and erosion, and the cost of the long run
// does not grow with the terrain. A coarser terrain (a 65^2 preview) takes
// the run's change at its own samples, the model's grid resampled from it:
// run on its own grid, its one-cell channels covered more of the land and
// it eroded 14 % more than its final.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/error.hpp"
#include "erosion/erosion.hpp"
#include "erosion/basin_graph.hpp"
#include "erosion/flow_graph.hpp"
#include "erosion/lake_fill.hpp"
#include "erosion/landscape_parts.hpp"
#include "erosion/model_constants.hpp"

namespace ft::erosion {
namespace {

// Steps: the knickpoint of a channel draining a sixteenth of the map moves
// at most this many cells per step; between kMinSteps and kMaxSteps. The
// implicit scheme is stable at any step. A 513^2 Rugged Mountains run at 8
// cells (half the steps of 4) eroded alike: its erosion depth correlated
// 0.995 with the run at 4 and its mean differed by 0.8 %; at 16 cells,
// 0.988 and 7 %.
constexpr double kCellsPerStep = 8.0;
constexpr int32_t kMinSteps = 2, kMaxSteps = kMaxModelSteps;

}  // namespace

int32_t steps_for(const D8Grid& g, const ErosionConfig& c, double years, int32_t most) {
  const double map_area = double(g.width - 1) * (g.height - 1) * g.spacing * g.spacing;
  const double celerity = c.fluvial.erodibility * std::pow(c.model.rainfall * map_area / 16, c.fluvial.area_exponent);
  const double cells = celerity * years / g.spacing;
  return int32_t(std::clamp(std::ceil(cells / kCellsPerStep), double(kMinSteps), double(most)));
}

// Bilinear sample of a w x h grid at fractional (fx, fy), clamped or wrapped.
float bilinear(const float* v, int32_t w, int32_t h, double fx, double fy, bool wrap) {
  auto split = [wrap](double f, int32_t n, int32_t& i0, int32_t& i1, double& t) {
    if (wrap) {
      f -= std::floor(f / n) * n;
      i0 = std::min(int32_t(f), n - 1);
      i1 = (i0 + 1) % n;
    } else {
      f = std::clamp(f, 0.0, double(n - 1));
      i0 = std::min(int32_t(f), n - 2);
      i1 = i0 + 1;
    }
    t = f - i0;
  };
  int32_t x0, x1, y0, y1;
  double tx, ty;
  split(fx, w, x0, x1, tx);
  split(fy, h, y0, y1, ty);
  const double top = (1 - tx) * v[size_t(y0) * w + x0] + tx * v[size_t(y0) * w + x1];
  const double bottom = (1 - tx) * v[size_t(y1) * w + x0] + tx * v[size_t(y1) * w + x1];
  return float((1 - ty) * top + ty * bottom);
}

// `from` (grid a) sampled at every node of grid b: both span the same
// terrain, corner to corner (bounded) or over one period (periodic).
std::vector<float> resample(const float* from, const D8Grid& a, const D8Grid& b) {
  const int32_t ea = a.periodic ? 0 : 1;
  const double sx = double(a.width - ea) / (b.width - ea), sy = double(a.height - ea) / (b.height - ea);
  std::vector<float> out(b.size());
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < b.height; ++y)
    for (int32_t x = 0; x < b.width; ++x)
      out[size_t(y) * b.width + x] = bilinear(from, a.width, a.height, x * sx, y * sy, a.periodic);
  return out;
}

// z averaged over (2r + 1)^2 cells around each cell (clamped at a bounded
// grid's edges, wrapped on a periodic one). The model's grid samples this,
// not z: point samples of a finer terrain carry its detail as noise on the
// model's cells, which the model's run then smooths away, and that change,
// resampled, wore the detail down at the model's nodes only (a pattern of
// the model's grid, and half the detail's energy at 513^2).
std::vector<float> box_mean(const float* z, const D8Grid& g, int32_t r) {
  const int32_t w = g.width, h = g.height;
  std::vector<float> rows(g.size()), out(g.size());
  auto at = [&](int32_t k, int32_t n) { return g.periodic ? (k % n + n) % n : std::clamp(k, 0, n - 1); };
  const double inv = 1.0 / double(2 * r + 1);
  // Running sums in double, so the cost does not grow with r (17 cells
  // across at 4097^2): along each row, then down each column, the columns
  // in blocks among the threads (each column's sums are the same however
  // they are split).
#pragma omp parallel for schedule(static)
  for (int32_t y = 0; y < h; ++y) {
    const float* row = z + size_t(y) * w;
    double sum = 0;
    for (int32_t d = -r; d <= r; ++d) sum += row[at(d, w)];
    for (int32_t x = 0; x < w; ++x) {
      rows[size_t(y) * w + x] = float(sum * inv);
      sum += double(row[at(x + r + 1, w)]) - row[at(x - r, w)];
    }
  }
  constexpr int32_t kBlock = 256;
  const int32_t blocks = (w + kBlock - 1) / kBlock;
#pragma omp parallel
  {
    std::vector<double> sum(kBlock);
#pragma omp for schedule(static)
    for (int32_t b = 0; b < blocks; ++b) {
      const int32_t x0 = b * kBlock, len = std::min(w, x0 + kBlock) - x0;
      std::fill(sum.begin(), sum.end(), 0.0);
      for (int32_t d = -r; d <= r; ++d) {
        const float* row = rows.data() + size_t(at(d, h)) * w + x0;
        for (int32_t x = 0; x < len; ++x) sum[x] += row[x];
      }
      for (int32_t y = 0; y < h; ++y) {
        float* dst = out.data() + size_t(y) * w + x0;
        const float* add = rows.data() + size_t(at(y + r + 1, h)) * w + x0;
        const float* sub = rows.data() + size_t(at(y - r, h)) * w + x0;
        for (int32_t x = 0; x < len; ++x) {
          dst[x] = float(sum[x] * inv);
          sum[x] += double(add[x]) - sub[x];
        }
      }
    }
  }
  return out;
}

// A deposit of mean depth d on a model cell, laid on the texture the model
// does not see (height z; `seen`, the model's surface before its run,
// resampled here; sd, the texture's spread about it over the cell).
// Sediment wears the texture and fills its hollows first:
// - worn: t becomes a t, a = exp(-(d / sd)^2 / 2): a thin deposit (d =
//   0.3 sd) keeps 96 % of its relief, d = 1.5 sd 32 %;
// - filled: every sample rises to at least seen + a sd l, with l such that
//   the mean rise is d for a normal texture: E[max(t, l)] - E[t] =
//   d / (a sd), that is phi(l) + l Phi(l) = d / (a sd).
// Where the erosion mask is below 1 the wear is scaled by it (`erodible`):
// where it is 0 a deposit only fills, it lowers no sample.
// A deep fill leaves the model's own plain (seen + d), as the preview has;
// a thin one fills only the deepest hollows. Added as z + d, the rock's
// texture stood on every filled lake of a final. Filled without wear, the
// texture's tail stood out of the plain (0.3 % of the samples at d = 2.7 sd).
// Filled about the box mean of z instead of `seen`, the plain kept the
// texture between that mean and the model's cell (2.6 mm spread on a
// levels-10 final), and the detail run's lakes filled over it, leaving its
// crests as pimples of 5-11 mm (70 on one floor where the preview is flat).
float bury(float z, float seen, double sd, double d, float erodible) {
  if (!(sd > 0) || d / sd < 1e-3) return float(z + d);  // level below -3 sd: the texture stays
  const double worn = 1.0 - erodible * (1.0 - std::exp(-0.5 * (d / sd) * (d / sd)));
  z = float(seen + worn * (double(z) - seen));  // in double: with worn 1 it is z, exactly
  sd *= worn;
  const double depth = d / sd;
  if (depth > 8) return std::max(z, float(seen + d));  // phi(l) ~ 0: l = depth (and sd may be 0)
  // Newton from l = depth (to the right of the root: the left side is
  // convex and increasing, phi + l Phi > l), so it converges from above.
  double l = depth;
  for (int iter = 0; iter < 30; ++iter) {
    const double phi = std::exp(-0.5 * l * l) / std::sqrt(2 * M_PI), cdf = 0.5 * std::erfc(-l / std::sqrt(2.0));
    const double step = (phi + l * cdf - depth) / cdf;
    l -= step;
    if (step < 1e-6) break;
  }
  return std::max(z, float(seen + sd * l));
}

namespace {

struct Run {
  const D8Grid& g;
  const ErosionConfig& c;
  const float* mask;  // null: 1
  const float* rain;  // null: 1
  MassBudget* budget;
  bool talus;         // limit slopes to the talus angle
  // Null: creep acts on z. Else creep acts on z - texture only: what the
  // run did, not the texture it started from (the detail run, see landscape()).
  const float* texture;
  // Null, or each cell's change by creep, added up (the model's run: its
  // change is resampled with the mask, see landscape()).
  float* crept = nullptr;
};

// One run of the model over its steps (see the file comment): the constants
// of its time step, its flow graph, and the grids its stages share. Each
// step: route(), then the stack's chunks (discharge, detachment and talus,
// deposition), then creep().
struct Evolution {
  const Run& run;
  const D8Grid& g;
  const ErosionConfig& c;
  float* z;
  const int32_t steps;
  const size_t n;
  const double cell, dt;
  const double k_dt, m, G;
  const double tan_talus;
  const double own_rain;  // water a cell gathers itself (x the rain map)
  const double shed;      // share of the excess over the talus shed per step
  FlowGraph graph;
  BasinGraph basins;
  const bool creeps;
  std::vector<float> filled, start, cap, diffused, plain, before_creep;
  std::vector<double> discharge, sediment;
  const int32_t sink;
  double carried = 0, detached = 0, deposited = 0;

  Evolution(const Run& r, float* heights, double years, int32_t step_count)
      : run(r),
        g(r.g),
        c(r.c),
        z(heights),
        steps(step_count),
        n(g.size()),
        cell(g.spacing * g.spacing),
        dt(years / steps),
        k_dt(c.fluvial.erodibility * dt),
        m(c.fluvial.area_exponent),
        G(c.model.deposition),
        tan_talus(r.talus ? std::tan(c.thermal.talus_degrees * M_PI / 180.0)
                          : std::numeric_limits<double>::infinity()),
        own_rain(c.model.rainfall * cell),
        shed(-std::expm1(-dt / c.model.scree_years)),
        creeps(c.fluvial.diffusion > 0),
        filled(n),
        start(n),
        cap(n),
        diffused(r.texture && creeps ? n : 0),
        plain(r.texture && creeps ? n : 0),
        before_creep(r.crept && creeps ? n : 0),
        discharge(n),
        sediment(n),
        sink(g.periodic ? periodic_sink(g, heights) : -1) {}

  double mask(int32_t i) const { return run.mask ? double(run.mask[i]) : 1.0; }

  // The step's flow graph over z, drained out of its depressions.
  void route(int32_t step, uint32_t level, const Progress& progress) {
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i) {
      start[i] = z[i];
      discharge[i] = own_rain * (run.rain ? run.rain[i] : 1.0f);
      cap[i] = std::numeric_limits<float>::infinity();
    }
    draw_rho8(g, sink, level * uint32_t(kMaxSteps) + uint32_t(step), graph);
    {
      // A step of a 4097^2 detail run takes seconds: the bar moves (and a
      // cancel is seen) within it too, at its phases' rough shares of the
      // time; the first step's global fill, the longest part, inside it.
      const ProgressPart routing(progress, double(step) / steps, 0.5 / steps);
      route_over_depressions(g, z, sink, graph, basins, filled.data(), routing.progress());
    }
    progress.report((step + 0.5) / steps);
  }

  // Runs of whole trees are independent: each is walked in stack order
  // (receivers first) or against it (donors first), so the result does
  // not depend on the thread count.
  void erode_and_deposit(int32_t step, const Progress& progress) {
    const int32_t chunks = int32_t(graph.chunk_start.size()) - 1;
    // Each chunk's volumes, added in chunk order after (a reduction's order
    // depends on the team: the mass budget would vary in its last digits).
    std::vector<std::array<double, 3>> volumes(size_t(std::max(chunks, 0)), {0.0, 0.0, 0.0});
    // In batches of chunks, with a report after each (a 4097^2 step's
    // incision takes seconds); chunks are independent, so the heights do
    // not depend on the batches.
    constexpr int32_t kBatches = 4;
    for (int32_t b = 0; b < kBatches; ++b) {
      const int32_t from = int32_t(int64_t(chunks) * b / kBatches), to = int32_t(int64_t(chunks) * (b + 1) / kBatches);
#pragma omp parallel for schedule(dynamic, 1)
      for (int32_t ch = from; ch < to; ++ch) {
        const int32_t first = graph.chunk_start[ch], last = graph.chunk_start[ch + 1];
        LakeFill lake(graph, filled.data(), start.data(), z, cell);
        accumulate_discharge(first, last);
        detach_and_shed(first, last);
        std::array<double, 3>& v = volumes[size_t(ch)];
        deposit(first, last, lake, v[0], v[1], v[2]);
      }
      progress.report((step + 0.5 + 0.35 * (b + 1) / kBatches) / steps);
    }
    for (const std::array<double, 3>& v : volumes) carried += v[0], detached += v[1], deposited += v[2];
  }

  // Discharge, donors first.
  void accumulate_discharge(int32_t first, int32_t last) {
    for (int32_t k = last - 1; k >= first; --k) {
      const int32_t i = graph.stack[k], r = graph.receiver[i];
      if (r != i) discharge[r] += discharge[i];
    }
  }

  // Detachment and talus, receivers first.
  void detach_and_shed(int32_t first, int32_t last) {
    for (int32_t k = first; k < last; ++k) {
      const int32_t i = graph.stack[k], r = graph.receiver[i];
      // A river that runs into a lake cuts down to the lake's surface,
      // its base level, not to the lake's floor.
      const float base = filled[r] > start[r] ? filled[r] : z[r];
      if (r == i || !(z[i] > base)) continue;  // a base level, or under a lake
      const double w = mask(i);
      const double f = w * k_dt * (m == 0.5 ? std::sqrt(discharge[i]) : std::pow(discharge[i], m)) / graph.length[i];
      double zi = (z[i] + f * base) / (1.0 + f);
      const double limit = base + tan_talus * graph.length[i];
      if (zi > limit) zi -= w * shed * (zi - limit);
      z[i] = float(zi);
    }
  }

  // Deposition, donors first; adds the chunk's volumes to the three sums.
  void deposit(int32_t first, int32_t last, LakeFill& lake, double& carried_step, double& detached_step,
               double& deposited_step) {
    for (int32_t k = last - 1; k >= first; --k) {
      const int32_t i = graph.stack[k], r = graph.receiver[i];
      const double lost = std::max(0.0, double(start[i]) - z[i]) * cell;
      detached_step += lost;
      double load = sediment[i] + lost;
      sediment[i] = 0;
      double laid = 0;
      if (lake.under(i)) {
        // A lake's cells pass what they get on to its exit, which
        // settles the lake's share at once (LakeFill). The share is
        // G, as on land: a lake traps what settles in still water and
        // the rest stays in suspension and flows on (a lake that kept
        // everything filled fBm's closed basins, on half its cells,
        // into plains, and Badlands, "little sediment kept", kept the
        // most).
        if (r != i && lake.in_lake_of(r, i)) {
          sediment[r] += load;
          continue;
        }
        laid = lake.fill(i, std::min(1.0, G) * load);
      } else if (r != i) {
        const double top = std::isinf(cap[i]) ? double(start[i]) : double(cap[i]);
        const double share = std::min(1.0, G * own_rain / std::max(discharge[i], 1e-30));
        laid = std::min(share * load, std::max(0.0, top - z[i]) * cell);
        z[i] = float(z[i] + laid / cell);
      }
      deposited_step += laid;
      if (r == i) {  // a base level: the load leaves (a bounded edge stays where it is)
        carried_step += load - laid;
        continue;
      }
      sediment[r] += std::max(0.0, load - laid);
      cap[r] = std::min(cap[r], float(z[i] - kFanSlope * graph.length[i]));
    }
  }

  // Hillslope creep, implicit; the sea floor and the outlets' base levels stay.
  void creep() {
    if (run.crept) std::copy(z, z + n, before_creep.begin());
    // The mask scales each edge's flux: outside it creep neither fills a
    // hollow nor rounds a crest (scaling creep's change instead let it
    // fill the hollows of the masked-off land).
    if (run.texture) {
      creep_beside_texture();
    } else {
      hillslope_diffusion(g, z, c.fluvial.diffusion * dt, run.mask);
    }
    if (g.sea) {  // the sea floor stays (creep would spread the coast over it)
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n); ++i)
        if (g.sea[i]) z[i] = start[i];
    }
    if (!g.periodic) {
      // Where water leaves the map, the edge cell is its base level:
      // creep may lower it, never raise it. Creep, closed at the edges,
      // filled these notches from the edge row beside them (by a median
      // of 2 cm on fBm 513^2, up to 7 cm) and silted the valleys' mouths
      // into flats. The other edge cells creep as the rest.
      const double outlet = kOutletCells * own_rain;
      g.for_each_edge_cell([&](size_t i) {
        if (discharge[i] >= outlet) z[i] = std::min(z[i], start[i]);
      });
    }
    if (run.crept) {
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n); ++i) run.crept[i] += z[i] - before_creep[i];
    }
  }

  // With a texture, a deposit (above it) creeps as it lies: sediment
  // has no rock texture, and creep on its change would print the
  // texture of the bed it buried onto a filled lake's flat.
  void creep_beside_texture() {
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i) {
      diffused[i] = z[i] - run.texture[i];
      plain[i] = z[i];
    }
    hillslope_diffusion(g, diffused.data(), c.fluvial.diffusion * dt, run.mask);
    hillslope_diffusion(g, plain.data(), c.fluvial.diffusion * dt, run.mask);
    // A sample of the texture beside a deposit is not lifted by the
    // deposit's creep above where plain creep would put it: a crest
    // standing out of a filled floor rode up with the floor (by 11 mm
    // on example 14's top lake) and stayed a pimple on it. (On every
    // sample, it wore the hillslopes' texture: 0.62 -> 0.54 of its
    // energy kept, Badlands at 1025^2.)
    auto beside_deposit = [&](int64_t i) {
      const int32_t x = int32_t(i % g.width), y = int32_t(i / g.width);
      for (int k = 0; k < 8; k += 2) {
        const int64_t j = g.neighbour(x, y, k);
        if (j >= 0 && z[j] > run.texture[j]) return true;
      }
      return false;
    };
    // Each cell's new height goes into `diffused` (it reads only its own
    // there), since its neighbours' z are read.
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i) {
      float next = plain[i];
      if (!(z[i] > run.texture[i])) {
        next = diffused[i] + run.texture[i];
        if (beside_deposit(i)) next = std::min(next, std::max(z[i], plain[i]));
      }
      diffused[i] = next;
    }
    // Added as a change (not assigned): the float rounding of the runs
    // without a mask stays as it was.
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n); ++i) z[i] += diffused[i] - z[i];
  }
};

// Evolves z for `years` in `steps` implicit steps (see the file comment).
void evolve(const Run& run, float* z, double years, int32_t steps, uint32_t level, const Progress& progress) {
  Evolution e(run, z, years, steps);
  for (int32_t step = 0; step < steps; ++step) {
    e.route(step, level, progress);
    e.erode_and_deposit(step, progress);
    if (e.creeps) e.creep();
    progress.report(double(step + 1) / steps);
  }
  if (run.budget) {
    run.budget->carried_out += e.carried;
    run.budget->detached += e.detached;
    run.budget->deposited += e.deposited;
  }
}

}  // namespace

void model_run(const D8Grid& g, const ErosionConfig& c, const float* mask, const float* rain, MassBudget* budget,
               float* crept, float* z, double years, int32_t steps, const Progress& progress) {
  evolve({g, c, mask, rain, budget, true, nullptr, crept}, z, years, steps, 0, progress);
}

}  // namespace ft::erosion
