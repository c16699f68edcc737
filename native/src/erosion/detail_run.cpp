// SPDX-License-Identifier: GPL-3.0-or-later
// The detail run on a region (see detail_run.hpp).
#include "erosion/detail_run.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <vector>

#include <omp.h>

#include "core/buffer.hpp"
#include "core/kernel_clones.hpp"
#include "core/rng.hpp"
#include "erosion/flow_graph.hpp"
#include "erosion/model_constants.hpp"

namespace ft::erosion {
namespace {

// How many receivers down water and sediment are followed within a step,
// and how many the implicit incision solves along. (A 4097^2 terrain's
// model cell is 16 samples across: the detail run resolves what lies below
// it, the model what lies above.)
constexpr int32_t kHops = 12;
constexpr int32_t kCutHops = 6;
// The waves' bands (DetailRun::wave): each band's hops also compute the
// kHops rows on either side that its hops read.
constexpr int32_t kBandRows = 64;
// Passes that lift the small pits of the surface water routes over.
constexpr int32_t kPitPasses = 3;
constexpr uint8_t kSelf = 8;  // a receiver of its own: a base level or a pit

// The grids of a run: not zero-filled on allocation (every pass writes a
// grid before it is read), and first touched by the team, not by one
// thread (the zeroing of 13 fresh grids was a sixth of a 2049^2 run).
using Floats = Buffer<float>;
using Bytes = Buffer<uint8_t>;

void copy_grid(const float* from, size_t n, float* to) {
#pragma omp parallel for schedule(static)
  for (int64_t i = 0; i < int64_t(n); ++i) to[i] = from[i];
}

// What the donors of cell i (bit k: neighbour k at offset o[k] drains to
// it) send: their fronts added in direction order. The neighbours that do
// not drain to i add 0, which changes no bit of a sum of non-negative
// terms, so this sums what the bits select without a branch per donor.
inline float pulled(const float* __restrict front, unsigned bits, int64_t i, const int32_t* o) {
  float in = 0.0f;
#pragma GCC unroll 8
  for (int k = 0; k < 8; ++k) {
    const float v = front[i + o[k]];
    in += ((bits >> k) & 1u) ? v : 0.0f;
  }
  return in;
}

// One hop of a wave (DetailRun::wave) on cells x0 .. x1 - 1 of an interior
// row (all eight neighbours at the offsets `off`), `row` the index of its
// first cell; returns how many cells send on. Restrict parameters of
// functions that are not inlined, so GCC vectorises them; each cell's sums
// are the general path's, in the same order, so the bits are too (a cell
// whose donors send nothing, which the general path skips, adds 0 and
// lays min(share x 0, room) = 0).
// The discharge: a cell adds what it takes to its discharge and sends it on.
[[gnu::noinline]] FT_KERNEL_CLONES int64_t discharge_hop(const float* __restrict front, float* __restrict next,
                                                         float* __restrict q, const uint8_t* __restrict donors,
                                                         const uint8_t* __restrict dir, const int32_t* off,
                                                         int64_t row, int32_t x0, int32_t x1) {
  const int32_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  int32_t moving = 0;  // (an int: a 64-bit count kept the AVX2 loop scalar)
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    const float in = pulled(front, donors[i], i, o);
    q[i] += in;
    const float out = dir[i] == kSelf ? 0.0f : in;
    next[i] = out;
    moving += out != 0.0f;
  }
  return moving;
}

// The sediment: a cell lays its share of what it takes, up to its room,
// and sends on the rest.
[[gnu::noinline]] FT_KERNEL_CLONES int64_t deposit_hop(const float* __restrict front, float* __restrict next,
                                                       const float* __restrict share, float* __restrict room,
                                                       float* __restrict laid, const uint8_t* __restrict donors,
                                                       const uint8_t* __restrict dir, const int32_t* off, int64_t row,
                                                       int32_t x0, int32_t x1) {
  const int32_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  int32_t moving = 0;  // (an int: a 64-bit count kept the AVX2 loop scalar)
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    const float in = pulled(front, donors[i], i, o);
    const float here = std::min(share[i] * in, room[i]);
    room[i] -= here;
    laid[i] += here;
    const float out = dir[i] == kSelf ? 0.0f : in - here;
    next[i] = out;
    moving += out != 0.0f;
  }
  return moving;
}

// Interior kernels of the grid passes (the rows' cells x0 .. x1 - 1 whose
// eight neighbours all lie in the region and which are not on the whole's
// edge: no bounds test per neighbour). Each does the general path's
// operations in its order, so the bits are the same; `sea` is the row's
// sea flags (all 0 without a sea).

// nextafter(v, +inf) of a finite v, without the call (which kept the loop
// scalar): the next float up, the smallest subnormal from either zero.
inline float next_up(float v) {
  const uint32_t u = std::bit_cast<uint32_t>(v);
  const uint32_t up = v == 0.0f ? 1u : (v > 0.0f ? u + 1u : u - 1u);
  return std::bit_cast<float>(up);
}

// One pit pass of the routing surface (DetailRun::routing_surface).
[[gnu::noinline]] FT_KERNEL_CLONES void lift_pits_row(const float* __restrict from, float* __restrict to,
                                                      const uint8_t* __restrict sea, const int32_t* off, int64_t row,
                                                      int32_t x0, int32_t x1) {
  const int32_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  const float inf = std::numeric_limits<float>::infinity();
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    float lowest = inf;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) lowest = std::min(lowest, from[i + o[k]]);
    if (sea[x]) lowest = inf;
    const float v = from[i];
    to[i] = v <= lowest && lowest != inf && lowest != -inf ? next_up(lowest) : v;
  }
}

// Steepest descent (DetailRun::route): the first direction of the largest
// positive drop, kSelf without one or on the sea; `random` is the row's
// Rho8 numbers, indexed like `sea`.
[[gnu::noinline]] FT_KERNEL_CLONES void descend_row(const float* __restrict zr, const float* __restrict random,
                                                    uint8_t* __restrict dir, const uint8_t* __restrict sea,
                                                    const int32_t* off, int64_t row, int32_t x0, int32_t x1) {
  const int32_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    const float wd = rho8_diagonal_weight(random[x]);
    float best = 0.0f;
    int32_t best_k = kSelf;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) {
      const float drop = (zr[i] - zr[i + o[k]]) * ((k & 1) ? wd : 1.0f);
      const bool better = drop > best;
      best = better ? drop : best;
      best_k = better ? k : best_k;
    }
    dir[i] = sea[x] ? kSelf : uint8_t(best_k);
  }
}

// The donors (DetailRun::find_donors): bit k for the neighbour k that drains here.
[[gnu::noinline]] FT_KERNEL_CLONES void donors_row(const uint8_t* __restrict dir, uint8_t* __restrict donors,
                                                   const int32_t* off, int64_t row, int32_t x0, int32_t x1) {
  const int32_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    uint32_t bits = 0;
#pragma GCC unroll 8
    for (int k = 0; k < 8; ++k) bits |= uint32_t(dir[i + o[k]] == ((k + 4) & 7)) << k;
    donors[i] = uint8_t(bits);
  }
}

// Deposit's setup (DetailRun::deposit) on an interior row: each cell's room
// below its donors' fan caps (a pit's up to its spill), its own loss, and
// the share it lays. `fan` is kFanSlope x the run of a straight and of a
// diagonal step, `rain` the row's rain map (1s without one), `pit_share`
// min(1, G): the general path's operations in its order.
struct DepositSetup {
  double fan[2];
  double cell, G, own_rain;
  float pit_share;
};

[[gnu::noinline]] FT_KERNEL_CLONES void deposit_setup_row(const float* __restrict z, const float* __restrict start,
                                                          const float* __restrict q, const uint8_t* __restrict dir,
                                                          const uint8_t* __restrict donors,
                                                          const uint8_t* __restrict sea, const float* __restrict rain,
                                                          float* __restrict room, float* __restrict laid,
                                                          float* __restrict front, float* __restrict share,
                                                          const int32_t* off, const DepositSetup& k, int64_t row,
                                                          int32_t x0, int32_t x1) {
  const int32_t o[8] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7]};
  const double fan0 = k.fan[0], fan1 = k.fan[1], cell = k.cell, G = k.G, own_rain = k.own_rain;
  const float pit_share = k.pit_share, inf = std::numeric_limits<float>::infinity();
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    float cap = inf, lowest = inf;
    const unsigned bits = donors[i];
#pragma GCC unroll 8
    for (int d = 0; d < 8; ++d) {
      const float zj = z[i + o[d]];
      lowest = std::min(lowest, zj);
      const float c = float(double(zj) - ((dir[i + o[d]] & 1) ? fan1 : fan0));
      cap = ((bits >> d) & 1u) ? std::min(cap, c) : cap;
    }
    const float own = start[i];  // (loaded unconditionally: a conditional load kept the loop scalar)
    float top = std::isinf(cap) ? own : cap;
    const bool self = dir[i] == kSelf;
    const bool pit = self & !sea[x];
    top = pit ? std::min(top, lowest) : top;
    room[i] = float(std::max(0.0, double(top) - z[i]) * cell);
    laid[i] = 0.0f;
    front[i] = float(std::max(0.0, double(own) - z[i]) * cell);
    const double r = own_rain * double(rain[x]);
    const float lays = float(std::min(1.0, G * r / std::max(double(q[i]), 1e-30)));
    share[i] = self ? (pit ? pit_share : 0.0f) : lays;
  }
}

// Incision's factors K dt sqrt(Q) / run (DetailRun::incise, m = 1/2) of
// cells x0 .. x1 - 1 (no neighbours read), the mask's (or 1s) indexed alike.
[[gnu::noinline]] FT_KERNEL_CLONES void incision_factors(const float* __restrict q, const uint8_t* __restrict dir,
                                                         const float* __restrict mask, float* __restrict f,
                                                         double k_dt, double straight, double diagonal, int64_t x0,
                                                         int64_t x1) {
  for (int64_t i = x0; i < x1; ++i) {
    const uint8_t d = dir[i];
    const float v = float(double(mask[i]) * k_dt * std::sqrt(double(q[i])) / ((d & 1) ? diagonal : straight));
    f[i] = d == kSelf ? 0.0f : v;
  }
}

// One sweep of the incision on an interior row: each cell solved against
// its receiver's height in `last` (a gather by its direction's offset).
[[gnu::noinline]] FT_KERNEL_CLONES void incise_row(const float* __restrict last, float* __restrict out,
                                                   const float* __restrict start, const float* __restrict f,
                                                   const uint8_t* __restrict dir, const int32_t* off, int64_t row,
                                                   int32_t x0, int32_t x1) {
  // Index kSelf: the cell itself (its result is its own start anyway).
  const int32_t o[9] = {off[0], off[1], off[2], off[3], off[4], off[5], off[6], off[7], 0};
  // Indexed within the row (32-bit gathers), the arrays from its start.
  const float *lr = last + row, *sr = start + row, *fr = f + row;
  const uint8_t* dr = dir + row;
  float* orow = out + row;
  for (int32_t x = x0; x < x1; ++x) {
    const int32_t d = dr[x];
    const float b = lr[x + o[d]];
    const float zi = sr[x];
    const double fi = fr[x];
    const float v = zi > b ? float((double(zi) + fi * b) / (1.0 + fi)) : zi;
    orow[x] = d == kSelf ? zi : v;
  }
}

// Creep's new heights (DetailRun::creep) on an interior row: a deposit
// creeps as it lies; elsewhere what the run did creeps beside the texture,
// never lifted above plain creep beside a deposit.
[[gnu::noinline]] FT_KERNEL_CLONES void creep_row(const float* __restrict z, const float* __restrict texture,
                                                  const float* __restrict diffused, const float* __restrict plain,
                                                  float* __restrict next, const int32_t* off, int64_t row, int32_t x0,
                                                  int32_t x1) {
  const int32_t o0 = off[0], o2 = off[2], o4 = off[4], o6 = off[6];
  for (int32_t x = x0; x < x1; ++x) {
    const int64_t i = row + x;
    const bool beside = (z[i + o0] > texture[i + o0]) | (z[i + o2] > texture[i + o2]) |
                        (z[i + o4] > texture[i + o4]) | (z[i + o6] > texture[i + o6]);
    const float p = plain[i], zi = z[i];
    const float rock = diffused[i] + texture[i];
    const float kept = beside ? std::min(rock, std::max(zi, p)) : rock;
    next[i] = zi > texture[i] ? p : kept;
  }
}

// Creep's kernel along one axis: `count` passes, each either a box of
// 2 radius + 1 samples or, where the step's variance is small, the
// three-tap [a, 1 - 2a, a].
struct CreepKernel {
  int32_t count = 0;
  int32_t radius[4] = {};
  float tap = 0;  // a of the three-tap passes (0: boxes)
  int32_t reach() const {
    int32_t r = 0;
    for (int32_t k = 0; k < count; ++k) r += tap > 0 ? 1 : radius[k];
    return r;
  }
};

// The passes whose variance is the implicit step's, 2 r (r = D dt /
// spacing^2, samples^2): up to four three-taps below a variance of 2, else
// three boxes of odd widths w_l and w_l + 2 (Kovesi 2010, "Fast almost-
// Gaussian filtering"), so the run creeps as far as the model's would.
CreepKernel creep_kernel(double r) {
  CreepKernel k;
  const double variance = 2 * r;
  if (!(variance > 1e-9)) return k;
  if (variance <= 2) {
    k.count = int32_t(std::ceil(variance / 0.5));
    k.tap = float(variance / (2 * k.count));
    for (int32_t p = 0; p < k.count; ++p) k.radius[p] = 1;
    return k;
  }
  const int32_t n = 3;
  int32_t wl = int32_t(std::floor(std::sqrt(12 * variance / n + 1)));
  if (wl % 2 == 0) --wl;
  const int32_t m = int32_t(std::lround((12 * variance - n * wl * wl - 4 * n * wl - 3 * n) / (-4.0 * wl - 4)));
  k.count = n;
  for (int32_t p = 0; p < n; ++p) k.radius[p] = ((p < m ? wl : wl + 2) - 1) / 2;
  return k;
}

double creep_r(const D8Grid& g, const ErosionConfig& c, double dt) {
  return c.fluvial.diffusion * dt / (g.spacing * g.spacing);
}

// One detail run's state on its region.
class DetailRun {
 public:
  DetailRun(const Region& r, const ErosionConfig& c, double years, int32_t steps, const DetailInputs& in, float* z)
      : r_(r), c_(c), in_(in), z_(z), w_(r.width), h_(r.height), n_(r.size()), steps_(steps),
        cell_(r.whole.spacing * r.whole.spacing), dt_(years / steps), k_dt_(c.fluvial.erodibility * dt_),
        m_(c.fluvial.area_exponent), G_(c.model.deposition), own_rain_(c.model.rainfall * cell_),
        kernel_(creep_kernel(creep_r(r.whole, c, dt_))), texture_(n_), start_(n_),
        random_(size_t(omp_get_max_threads()) * size_t(r.width)), dir_(n_),
        q_(n_), front_(n_), next_(n_), cut_(n_), room_(n_), laid_(n_), donors_(n_) {
    for (int k = 0; k < 8; ++k) off_[k] = kDy[k] * w_ + kDx[k];
    no_sea_ = Bytes(size_t(w_));
    std::fill(no_sea_.begin(), no_sea_.end(), uint8_t(0));
    ones_ = Floats(size_t(w_));
    std::fill(ones_.begin(), ones_.end(), 1.0f);
    copy_grid(z, n_, texture_.data());
  }

  void step(int32_t s) {
    copy_grid(z_, n_, start_.data());
    route(s);
    find_donors();
    discharge();
    incise();
    deposit();
    if (kernel_.count > 0) creep();
    if (in_.sea) {
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n_); ++i)
        if (in_.sea[i]) z_[i] = start_[i];
    }
    keep_outlets();
  }

 private:
  bool inside(int32_t x, int32_t y) const { return x >= 0 && y >= 0 && x < w_ && y < h_; }
  bool interior(int32_t x, int32_t y) const { return x > 0 && y > 0 && x < w_ - 1 && y < h_ - 1; }
  bool base(int32_t x, int32_t y, size_t i) const { return r_.on_whole_edge(x, y) || (in_.sea && in_.sea[i]); }
  float run_of(uint8_t d) const { return float((d & 1) ? r_.whole.spacing * M_SQRT2 : r_.whole.spacing); }
  double rain(size_t i) const { return own_rain_ * (in_.rain ? double(in_.rain[i]) : 1.0); }

  // A pass over every cell: cell(x, y) on the region's edge and the whole's,
  // kernel(row, x0, x1) on the rest of a row (an interior kernel above).
  // begin(y) runs first, on the thread that does row y.
  template <class Cell, class Kernel, class Begin = void (*)(int32_t)>
  void rows(Cell cell, Kernel kernel, Begin begin = [](int32_t) {}) {
    // The whole's edge columns inside the region (none unless it is bounded
    // and the region reaches it) go to cell() too.
    const int64_t first = r_.whole.periodic ? 1 : std::max<int64_t>(1, 1 - int64_t(r_.x0));
    const int64_t last = r_.whole.periodic ? w_ - 1 : std::min<int64_t>(w_ - 1, r_.whole.width - 1 - int64_t(r_.x0));
    const int32_t x0 = int32_t(std::min<int64_t>(first, w_)), x1 = int32_t(std::max<int64_t>(last, x0));
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h_; ++y) {
      begin(y);
      if (y == 0 || y == h_ - 1 || w_ < 3 || r_.on_whole_edge(x0, y) || x1 <= x0) {
        for (int32_t x = 0; x < w_; ++x) cell(x, y);
        continue;
      }
      for (int32_t x = 0; x < x0; ++x) cell(x, y);
      kernel(int64_t(y) * w_, x0, x1);
      for (int32_t x = x1; x < w_; ++x) cell(x, y);
    }
  }
  // The sea flags of the row starting at `row` (0s without a sea).
  const uint8_t* sea_row(int64_t row) const { return in_.sea ? in_.sea + row : no_sea_.data(); }
  // The rain map's row starting at `row` (1s without a map).
  const float* rain_row(int64_t row) const { return in_.rain ? in_.rain + row : ones_.data(); }

  // Rho8's numbers of step s for row y, keyed by the samples' positions in
  // the whole, into the calling thread's row of random_ (drawn as each row
  // is routed: a grid of them was written and read once per step).
  float* draw_row(int32_t s, int32_t y) {
    float* out = random_.data() + size_t(omp_get_thread_num()) * w_;
    const uint32_t level = 1 * uint32_t(kMaxModelSteps) + uint32_t(s);
    draw_uniforms_at(r_.whole, in_.origin_x, in_.origin_y, level, Stream::kFluvialRouting, r_.y0 + y, r_.x0, w_, out);
    return out;
  }

  // The surface water routes over: z with its small pits raised, each pass
  // lifting every cell with no lower neighbour a float step above its
  // lowest (a pit of the rock's texture then passes its water on; what a
  // few passes do not drain keeps it). Into `out`, using `scratch`.
  void routing_surface(Floats& out, Floats& scratch) {
    // The passes alternate between scratch and out, the first from z_.
    static_assert(kPitPasses % 2 == 1);
    const float* from = z_;
    for (int32_t pass = 0; pass < kPitPasses; ++pass) {
      float* to = pass % 2 == 0 ? scratch.data() : out.data();
      rows(
          [&](int32_t x, int32_t y) {
            const size_t i = size_t(y) * w_ + x;
            float lowest = std::numeric_limits<float>::infinity();
            if (!base(x, y, i)) {
              const bool all = interior(x, y);
              for (int k = 0; k < 8; ++k)
                if (all || inside(x + kDx[k], y + kDy[k])) lowest = std::min(lowest, from[i + off_[k]]);
            }
            to[i] = from[i] <= lowest && !std::isinf(lowest) ? std::nextafter(lowest, INFINITY) : from[i];
          },
          [&](int64_t row, int32_t x0, int32_t x1) { lift_pits_row(from, to, sea_row(row), off_, row, x0, x1); });
      from = to;
    }
    std::swap(out, scratch);  // the last pass wrote scratch
  }

  // Steepest descent on the routing surface (ties: the first direction),
  // diagonals over 2 - r.
  void route(int32_t s) {
    Floats& zr = cut_;  // free until incise()
    routing_surface(zr, next_);
    rows(
        [&](int32_t x, int32_t y) {
          const size_t i = size_t(y) * w_ + x;
          uint8_t best_k = kSelf;
          if (!base(x, y, i)) {
            const float wd = rho8_diagonal_weight(random_[size_t(omp_get_thread_num()) * w_ + x]);
            const bool all = interior(x, y);
            float best = 0.0f;
            for (int k = 0; k < 8; ++k) {
              if (!all && !inside(x + kDx[k], y + kDy[k])) continue;
              const float drop = (zr[i] - zr[i + off_[k]]) * ((k & 1) ? wd : 1.0f);
              if (drop > best) best = drop, best_k = uint8_t(k);
            }
          }
          dir_[i] = best_k;
        },
        [&](int64_t row, int32_t x0, int32_t x1) {
          descend_row(zr.data(), random_.data() + size_t(omp_get_thread_num()) * w_, dir_.data(), sea_row(row), off_,
                      row, x0, x1);
        },
        [&](int32_t y) { draw_row(s, y); });
  }

  // Each cell's donors, one bit per direction: the neighbours that drain to it.
  void find_donors() {
    rows(
        [&](int32_t x, int32_t y) {
          const size_t i = size_t(y) * w_ + x;
          const bool all = interior(x, y);
          uint8_t bits = 0;
          for (int k = 0; k < 8; ++k)
            if ((all || inside(x + kDx[k], y + kDy[k])) && dir_[i + off_[k]] == ((k + 4) & 7))
              bits |= uint8_t(1u << k);
          donors_[i] = bits;
        },
        [&](int64_t row, int32_t x0, int32_t x1) { donors_row(dir_.data(), donors_.data(), off_, row, x0, x1); });
  }

  // kHops waves down the receivers from front_ (what each cell sends at
  // the first): each hop every cell takes what its donors send, adds it to
  // its discharge (kSediment: lays its share of it, up to its room) and
  // sends on the rest (nothing from a cell that is its own receiver).
  // In bands of kBandRows rows: a band's hop h is computed on the band
  // grown by the kHops - h hops still to come (the rows they read), its
  // fronts in the thread's own rows, so they stay in cache instead of
  // crossing memory twice a hop; the grown rows' discharge goes nowhere,
  // their room is a copy taken before any band starts. Each cell's sums
  // are those of a hop over the whole grid at a time, in the same order.
  template <bool kSediment>
  void wave() {
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n_); ++i)
      if (dir_[i] == kSelf) front_[i] = 0.0f;
    const int32_t bands = (h_ + kBandRows - 1) / kBandRows;
    const size_t w = size_t(w_);
    // The room of each band's grown rows: kHops above it, kHops below.
    if (kSediment) {
      if (halo_.size() < size_t(bands) * 2 * kHops * w) halo_ = Floats(size_t(bands) * 2 * kHops * w);
#pragma omp parallel for schedule(static)
      for (int32_t band = 0; band < bands; ++band) {
        const int32_t a = band * kBandRows, b = std::min(h_, a + kBandRows);
        for (int32_t y = std::max(0, a - kHops); y < std::min(h_, b + kHops); ++y)
          if (y < a || y >= b) std::copy_n(room_.data() + y * w, w, halo_row(band, a, b, y));
      }
    }
    const size_t rows_per_thread = size_t(kBandRows + 2 * kHops + 1);
    if (local_.size() < size_t(omp_get_max_threads()) * 2 * rows_per_thread * w)
      local_ = Floats(size_t(omp_get_max_threads()) * 2 * rows_per_thread * w);
#pragma omp parallel for schedule(dynamic, 1)
    for (int32_t band = 0; band < bands; ++band) {
      const int32_t a = band * kBandRows, b = std::min(h_, a + kBandRows);
      const int32_t lo = std::max(0, a - kHops);
      float* mine = local_.data() + size_t(omp_get_thread_num()) * 2 * rows_per_thread * w;
      float* fronts[2] = {mine, mine + rows_per_thread * w};  // row y at (y - lo) * w
      float* junk = mine + (rows_per_thread - 1) * w;         // the grown rows' discharge and deposit
      float* junk2 = fronts[1] + (rows_per_thread - 1) * w;
      std::fill_n(junk, w, 0.0f);
      std::fill_n(junk2, w, 0.0f);
      for (int32_t h = 1; h <= kHops; ++h) {
        const int32_t y0 = std::max(0, a - (kHops - h)), y1 = std::min(h_, b + (kHops - h));
        float* in_rows = fronts[h % 2];
        float* out_rows = fronts[(h + 1) % 2];
        int64_t moving = 0;
        for (int32_t y = y0; y < y1; ++y) {
          const float* in = h == 1 ? front_.data() + y * w : in_rows + size_t(y - lo) * w;
          float* out = out_rows + size_t(y - lo) * w;
          const bool own = y >= a && y < b;
          const size_t row = size_t(y) * w;
          float* state = kSediment ? (own ? room_.data() + row : halo_row(band, a, b, y)) : (own ? q_.data() + row : junk);
          float* laid = own ? laid_.data() + row : junk2;
          const uint8_t* donors = donors_.data() + row;
          const uint8_t* dir = dir_.data() + row;
          // A cell at the region's edge: its donors one by one.
          auto edge = [&](int32_t x) {
            float sum = 0.0f;
            for (unsigned bits = donors[x]; bits; bits &= bits - 1) sum += in[x + off_[std::countr_zero(bits)]];
            float send = 0.0f;
            if (sum != 0.0f) {
              if (kSediment) {
                const float here = std::min(cut_[row + x] * sum, state[x]);
                state[x] -= here;
                laid[x] += here;
                send = sum - here;
              } else {
                state[x] += sum;
                send = sum;
              }
            }
            out[x] = dir[x] == kSelf ? 0.0f : send;
            return int64_t(out[x] != 0.0f);
          };
          if (y == 0 || y == h_ - 1 || w_ < 3) {
            for (int32_t x = 0; x < w_; ++x) moving += edge(x);
            continue;
          }
          moving += edge(0) + edge(w_ - 1);
          moving += kSediment ? deposit_hop(in, out, cut_.data() + row, state, laid, donors, dir, off_, 0, 1, w_ - 1)
                              : discharge_hop(in, out, state, donors, dir, off_, 0, 1, w_ - 1);
        }
        // Nothing moves in the band's rows or those it reads: nothing reaches it later.
        if (moving == 0) break;
      }
    }
  }

  // The room of grown row y of band [a, b) (wave), kept per band.
  float* halo_row(int32_t band, int32_t a, int32_t b, int32_t y) {
    const int32_t slot = y < a ? y - (a - kHops) : kHops + (y - b);
    return halo_.data() + (size_t(band) * 2 * kHops + size_t(slot)) * size_t(w_);
  }

  // Discharge: the rain of every cell whose way down reaches this one within kHops.
  void discharge() {
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n_); ++i) q_[i] = front_[i] = float(rain(size_t(i)));
    wave<false>();
  }

  // Stream power, implicit along the next kCutHops receivers: each sweep
  // solves every cell against its receiver's last height (the first
  // against the step's start).
  void incise() {
    Floats& f = room_;  // the factors, until deposit() needs the room
    if (m_ == 0.5) {
#pragma omp parallel for schedule(static)
      for (int32_t y = 0; y < h_; ++y) {
        const int64_t row = int64_t(y) * w_;
        incision_factors(q_.data() + row, dir_.data() + row, in_.mask ? in_.mask + row : ones_.data(), f.data() + row,
                         k_dt_, run_of(0), run_of(1), 0, w_);
      }
    } else {
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n_); ++i) {
        const uint8_t d = dir_[i];
        const double w = in_.mask ? double(in_.mask[i]) : 1.0;
        f[i] = d == kSelf ? 0.0f : float(w * k_dt_ * std::pow(double(q_[i]), m_) / run_of(d));
      }
    }
    // Sweeps alternate between cut_ and z_, the last into z_.
    static_assert(kCutHops % 2 == 0);
    for (int32_t sweep = 0; sweep < kCutHops; ++sweep) {
      const float* last = sweep == 0 ? start_.data() : sweep % 2 == 1 ? cut_.data() : z_;
      float* out = sweep % 2 == 0 ? cut_.data() : z_;
      rows(
          [&](int32_t x, int32_t y) {
            const size_t i = size_t(y) * w_ + x;
            const uint8_t d = dir_[i];
            const float zi = start_[i];
            if (d == kSelf) {
              out[i] = zi;
              return;
            }
            const float b = last[i + off_[d]];
            out[i] = zi > b ? float((double(zi) + double(f[i]) * b) / (1.0 + double(f[i]))) : zi;
          },
          [&](int64_t row, int32_t x0, int32_t x1) {
            incise_row(last, out, start_.data(), f.data(), dir_.data(), off_, row, x0, x1);
          });
    }
  }

  // What was detached flows down at most kHops receivers, each cell laying
  // its share up to the room below the cells it came from.
  void deposit() {
    const float inf = std::numeric_limits<float>::infinity();
    rows(
        [&](int32_t x, int32_t y) {
          const size_t i = size_t(y) * w_ + x;
          const bool all = interior(x, y);
          float cap = inf, lowest = inf;
          for (int k = 0; k < 8; ++k) {
            if (!all && !inside(x + kDx[k], y + kDy[k])) continue;
            const size_t j = i + off_[k];
            lowest = std::min(lowest, z_[j]);
            if (donors_[i] >> k & 1) cap = std::min(cap, float(z_[j] - kFanSlope * run_of(dir_[j])));
          }
          float top = std::isinf(cap) ? start_[i] : cap;
          const bool pit = dir_[i] == kSelf && !base(x, y, i);
          if (pit) top = std::min(top, lowest);  // a pit fills to its spill
          room_[i] = float(std::max(0.0, double(top) - z_[i]) * cell_);
          laid_[i] = 0.0f;
          front_[i] = float(std::max(0.0, double(start_[i]) - z_[i]) * cell_);
          cut_[i] = dir_[i] == kSelf ? (pit ? float(std::min(1.0, G_)) : 0.0f)
                                     : float(std::min(1.0, G_ * rain(i) / std::max(double(q_[i]), 1e-30)));
        },
        [&](int64_t row, int32_t x0, int32_t x1) {
          const DepositSetup k{{kFanSlope * run_of(0), kFanSlope * run_of(1)}, cell_, G_, own_rain_,
                               float(std::min(1.0, G_))};
          deposit_setup_row(z_, start_.data(), q_.data(), dir_.data(), donors_.data(), sea_row(row),
                            rain_row(row), room_.data(), laid_.data(), front_.data(), cut_.data(), off_, k, row, x0,
                            x1);
        });
    // The first hop: each cell's own loss, where it was detached.
    const Floats& share = cut_;
    auto lay = [this, &share](size_t i, float in) {
      const float laid = std::min(share[i] * in, room_[i]);
      room_[i] -= laid;
      laid_[i] += laid;
      return in - laid;
    };
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n_); ++i) front_[i] = lay(size_t(i), front_[i]);
    wave<true>();  // share: cut_
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n_); ++i) z_[i] = float(z_[i] + double(laid_[i]) / cell_);
  }

  // Creep of what the run did, a deposit as it lies (landscape.cpp's rule:
  // sediment has no rock texture), and a sample beside a deposit never
  // lifted above where plain creep puts it.
  void creep() {
    Floats& diffused = front_;
    Floats& plain = next_;
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n_); ++i) {
      diffused[i] = z_[i] - texture_[i];
      plain[i] = z_[i];
    }
    blur(diffused);
    blur(plain);
    auto beside_deposit = [&](int32_t x, int32_t y, size_t i) {
      for (int k = 0; k < 8; k += 2)
        if (inside(x + kDx[k], y + kDy[k]) && z_[i + off_[k]] > texture_[i + off_[k]]) return true;
      return false;
    };
    Floats& next = cut_;
    rows(
        [&](int32_t x, int32_t y) {
          const size_t i = size_t(y) * w_ + x;
          float v = plain[i];
          if (!(z_[i] > texture_[i])) {
            v = diffused[i] + texture_[i];
            if (beside_deposit(x, y, i)) v = std::min(v, std::max(z_[i], plain[i]));
          }
          next[i] = v;
        },
        [&](int64_t row, int32_t x0, int32_t x1) {
          creep_row(z_, texture_.data(), diffused.data(), plain.data(), next.data(), off_, row, x0, x1);
        });
#pragma omp parallel for schedule(static)
    for (int64_t i = 0; i < int64_t(n_); ++i) z_[i] += next[i] - z_[i];
  }

  // The kernel along rows, then along columns; under a mask the change is
  // scaled by it (where it is 0, creep changes nothing).
  void blur(Floats& f) {
    Floats& original = laid_;  // free after deposit()
    if (in_.mask) copy_grid(f.data(), n_, original.data());
    passes_along_rows(f);
    for (int32_t p = 0; p < kernel_.count; ++p) pass_along_columns(f, kernel_.radius[p]);
    if (in_.mask) {
#pragma omp parallel for schedule(static)
      for (int64_t i = 0; i < int64_t(n_); ++i) f[i] = original[i] + in_.mask[i] * (f[i] - original[i]);
    }
  }

  // Local index of position v + d along an axis of `len` samples whose first
  // is `first` in a whole of `whole` samples: mirrored past a bounded
  // whole's edge (closed: no flux), clamped at the region's own edge.
  int32_t along(int32_t v, int32_t d, int32_t len, int64_t first, int32_t whole) const {
    int64_t g = first + v + d;
    if (!r_.whole.periodic) {
      if (g < 0) g = -g - 1;
      if (g >= whole) g = 2 * int64_t(whole) - g - 1;
    }
    return int32_t(std::clamp<int64_t>(g - first, 0, len - 1));
  }

  // Every pass along a row, one row after another (a row's passes read
  // only that row: it stays in cache).
  void passes_along_rows(Floats& f) {
    const bool tap = kernel_.tap > 0;
    const float a = kernel_.tap;
    int32_t widest = 0;
    for (int32_t p = 0; p < kernel_.count; ++p) widest = std::max(widest, kernel_.radius[p]);
#pragma omp parallel
    {
      std::vector<float> ext(size_t(w_) + 2 * size_t(widest));
#pragma omp for schedule(static)
      for (int32_t y = 0; y < h_; ++y) {
        float* row = f.data() + size_t(y) * w_;
        for (int32_t p = 0; p < kernel_.count; ++p) {
          const int32_t radius = kernel_.radius[p];
          const float inv = 1.0f / float(2 * radius + 1);
          std::copy(row, row + w_, ext.begin() + radius);
          for (int32_t x = -radius; x < 0; ++x) ext[size_t(x + radius)] = row[along(x, 0, w_, r_.x0, r_.whole.width)];
          for (int32_t x = w_; x < w_ + radius; ++x)
            ext[size_t(x + radius)] = row[along(x, 0, w_, r_.x0, r_.whole.width)];
          if (tap) {
            for (int32_t x = 0; x < w_; ++x) row[x] = a * ext[x] + (1 - 2 * a) * ext[x + 1] + a * ext[x + 2];
            continue;
          }
          for (int32_t x = 0; x < w_; ++x) row[x] = 0.0f;
          for (int32_t d = 0; d <= 2 * radius; ++d)
            for (int32_t x = 0; x < w_; ++x) row[x] += ext[size_t(x + d)];
          for (int32_t x = 0; x < w_; ++x) row[x] *= inv;
        }
      }
    }
  }

  void pass_along_columns(Floats& f, int32_t radius) {
    const bool tap = kernel_.tap > 0;
    const float a = kernel_.tap, inv = 1.0f / float(2 * radius + 1);
    Floats& out = room_;  // free after deposit(); incise() writes it before reading
#pragma omp parallel for schedule(static)
    for (int32_t y = 0; y < h_; ++y) {
      float* dst = out.data() + size_t(y) * w_;
      if (tap) {
        const float* up = f.data() + size_t(along(y, -1, h_, r_.y0, r_.whole.height)) * w_;
        const float* mid = f.data() + size_t(y) * w_;
        const float* down = f.data() + size_t(along(y, 1, h_, r_.y0, r_.whole.height)) * w_;
        for (int32_t x = 0; x < w_; ++x) dst[x] = a * up[x] + (1 - 2 * a) * mid[x] + a * down[x];
        continue;
      }
      for (int32_t x = 0; x < w_; ++x) dst[x] = 0.0f;
      for (int32_t d = -radius; d <= radius; ++d) {
        const float* src = f.data() + size_t(along(y, d, h_, r_.y0, r_.whole.height)) * w_;
        for (int32_t x = 0; x < w_; ++x) dst[x] += src[x];
      }
      for (int32_t x = 0; x < w_; ++x) dst[x] *= inv;
    }
    std::swap(f, out);
  }

  // Where water leaves a bounded map, the edge cell is its base level:
  // creep may lower it, never raise it (landscape.cpp).
  void keep_outlets() {
    if (r_.whole.periodic) return;
    const double outlet = kOutletCells * own_rain_;
    auto keep = [&](int32_t x, int32_t y) {
      const size_t i = size_t(y) * w_ + x;
      if (r_.on_whole_edge(x, y) && q_[i] >= outlet) z_[i] = std::min(z_[i], start_[i]);
    };
    // Only the whole's edge: its rows in the region, and its columns.
    const int64_t left = -r_.x0, right = r_.whole.width - 1 - r_.x0;
    for (int32_t y = 0; y < h_; ++y) {
      const int64_t gy = r_.y0 + y;
      if (gy == 0 || gy == r_.whole.height - 1) {
        for (int32_t x = 0; x < w_; ++x) keep(x, y);
        continue;
      }
      if (left >= 0 && left < w_) keep(int32_t(left), y);
      if (right >= 0 && right < w_ && right != left) keep(int32_t(right), y);
    }
  }

  const Region& r_;
  const ErosionConfig& c_;
  const DetailInputs& in_;
  float* z_;
  const int32_t w_, h_;
  const size_t n_;
  const int32_t steps_;
  const double cell_, dt_, k_dt_, m_, G_, own_rain_;
  const CreepKernel kernel_;
  int32_t off_[8];
  Floats texture_;  // z at the start of the run
  Floats start_;
  Floats random_;  // a row of Rho8's numbers per thread
  Bytes dir_;
  Floats q_, front_, next_, cut_, room_, laid_;
  Bytes donors_;
  Bytes no_sea_;    // a row of 0s: the sea flags without a sea
  Floats halo_;     // the waves' copies of the room beside each band
  Floats local_;    // the waves' fronts, two sets of a band's rows per thread
  Floats ones_;     // a row of 1s: the rain map (or mask) without one
};

}  // namespace

int32_t detail_reach(const D8Grid& g, const ErosionConfig& c, double years, int32_t steps) {
  if (!(years > 0) || steps < 1) return 0;
  // Per step: the routing (its pit passes and 1), discharge (kHops + 1), the incision's chain
  // (kCutHops), the sediment's way (kHops, its caps 1), creep (its kernel,
  // and the deposits beside a sample, 1), and a sample of margin.
  const int32_t creep = c.fluvial.diffusion > 0 ? creep_kernel(creep_r(g, c, years / steps)).reach() : 0;
  return steps * (kPitPasses + 1 + kHops + 1 + kCutHops + kHops + 1 + creep + 1 + 1);
}

void detail_run(const Region& r, const ErosionConfig& c, double years, int32_t steps, const DetailInputs& in, float* z,
                const Progress& progress) {
  if (!(years > 0) || steps < 1 || r.size() == 0) return;
  DetailRun run(r, c, years, steps, in, z);
  for (int32_t s = 0; s < steps; ++s) {
    run.step(s);
    progress.report(double(s + 1) / steps);
  }
}

}  // namespace ft::erosion
