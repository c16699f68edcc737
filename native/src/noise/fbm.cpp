// SPDX-License-Identifier: GPL-3.0-or-later
#include "noise/fbm.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"
#include "core/parallel_rows.hpp"
#include "core/rng.hpp"
#include "noise/basis.hpp"
#include "noise/basis_simd.hpp"
#include "noise/octave.hpp"
#include "noise/octave_sum.hpp"

namespace ft::noise {
namespace {

using namespace detail;

struct Plan {
  std::vector<Octave> octaves;
  std::vector<Octave> warp_x, warp_y;  // the domain-warp fbm, two independent fields
  int32_t basis = kBasisGradient;
  int32_t variant = kFbmStandard;
  bool periodic = false;
  float offset = 1;
  float scale = 1;        // applied to the sum: sigma, or sigma / sum a_i
  float warp_u = 0, warp_v = 0;  // warp displacement per unit of warp noise, in (u, v) units
};

// Octave i of a field takes its random numbers from Counter{0, i, stream}:
// the main octaves from Stream::kNoise, the two warp fields from their own
// streams, so no two uses share random numbers.
constexpr int kWarpOctaves = 4;

std::vector<Octave> make_octaves(const FbmConfig& c, int count, double lacunarity, double gain,
                                 Stream stream) {
  std::vector<Octave> out(static_cast<size_t>(count));
  const double aspect = double(c.height) / double(c.width);
  double f = c.frequency, a = 1.0;
  for (int i = 0; i < count; ++i, f *= lacunarity, a *= gain) {
    Octave& o = out[size_t(i)];
    const auto r = philox_block(c.seed, Counter{0, uint32_t(i), stream}, 0);
    o.key = r.v[0];
    o.amp = float(a);
    if (c.periodic) {
      // Whole cells per period; u = x / width and v = y / height both run over [0, 1).
      o.px = int32_t(std::max(1.0, std::round(f)));
      o.py = int32_t(std::max(1.0, std::round(f * aspect)));
      o.ipx = 1.0f / float(o.px);
      o.ipy = 1.0f / float(o.py);
      o.a11 = float(o.px);
      o.a22 = float(o.py);
      o.a12 = o.a21 = 0.0f;
      // Any shift keeps the noise periodic (the lattice wraps, not the
      // shift); a fractional one keeps the octaves' cell edges, which nest
      // when the periods double, from lining up.
      o.ox = float(double(r.v[1] >> 8) * (double(o.px) / 16777216.0));
      o.oy = float(double(r.v[2] >> 8) * (double(o.py) / 16777216.0));
    } else {
      const double t = c.rotation * i, cs = std::cos(t), sn = std::sin(t);
      o.a11 = float(f * cs);
      o.a12 = float(-f * sn);
      o.a21 = float(f * sn);
      o.a22 = float(f * cs);
      // A random origin per octave in [0, 256) cells: the lattice zeros of
      // the octaves do not line up at (0, 0).
      o.ox = float(double(r.v[1] >> 8) * (256.0 / 16777216.0));
      o.oy = float(double(r.v[2] >> 8) * (256.0 / 16777216.0));
    }
  }
  return out;
}

Plan make_plan(const FbmConfig& c) {
  Plan p;
  const double gain = effective_gain(c);
  p.octaves = make_octaves(c, c.octaves, c.lacunarity, gain, Stream::kNoise);
  p.basis = c.basis;
  p.variant = c.variant;
  p.periodic = c.periodic;
  p.offset = float(c.offset);
  double sum = 0;
  for (const Octave& o : p.octaves) sum += o.amp;
  const bool bounded = c.variant == kFbmStandard || c.variant == kFbmRidged;
  p.scale = float(bounded ? c.sigma / sum : c.sigma);
  if (c.warp > 0) {
    // Quilez's warp f(p + w q(p)) with q two independent 4-octave gradient
    // fbms normalised to about [-1, 1]; w is in base-octave cells.
    p.warp_x = make_octaves(c, kWarpOctaves, 2.0, 0.5, Stream::kNoiseWarpX);
    p.warp_y = make_octaves(c, kWarpOctaves, 2.0, 0.5, Stream::kNoiseWarpY);
    double wsum = 0;
    for (const Octave& o : p.warp_x) wsum += o.amp;
    const double su = c.periodic ? p.octaves[0].px : c.frequency;
    const double sv = c.periodic ? p.octaves[0].py : c.frequency;
    p.warp_u = float(c.warp / (wsum * su));
    p.warp_v = float(c.warp / (wsum * sv));
  }
  return p;
}

// ---------------------------------------------------------------------------
// The hot part: one chunk of one row. Everything below is always_inline so
// that it is compiled inside each of the two dispatch wrappers.
#define FT_INLINE [[gnu::always_inline]] inline

constexpr int kChunk = 256;  // samples per chunk: 5 arrays of 1 KiB stay in L1

// The instruction set a copy of the octave loop is compiled for (the
// dispatch wrappers below): the explicit-vector rows of basis_simd.hpp are
// called only from their own set's copy.
enum Isa { kIsaBaseline, kIsaAvx2, kIsaAvx512 };

// Whether a copy has basis_simd.hpp's rows (value, gradient, simplex; not periodic).
template <int kIsa, bool kPeriodic>
constexpr bool kSimdRows = kIsa != kIsaBaseline && !kPeriodic;
template <int kIsa>
FT_INLINE void simd_noise_row(int basis, const Octave& o, int n, const float* u, const float* v, bool v_const,
                              int mode, float amp, float* out) {
  if constexpr (kIsa == kIsaAvx512)
    simd_avx512::noise_row(basis, o, n, u, v, v_const, mode, amp, out);
  else
    simd_avx2::noise_row(basis, o, n, u, v, v_const, mode, amp, out);
}

// noise(M (u, v) + o) for n samples into out[]: the one noise call of the
// octave loop. v_const: every v[i] is v[0] (no warp before this octave).
template <int kIsa, int kBasis, bool kPeriodic>
FT_INLINE void basis_row(const Octave& o, int n, const float* u, const float* v, bool v_const, float* out) {
  if constexpr (kSimdRows<kIsa, kPeriodic> && kBasis <= kBasisSimplex)
    return simd_noise_row<kIsa>(kBasis, o, n, u, v, v_const, kStore, 1.0f, out);
  const float a11 = o.a11, a12 = o.a12, a21 = o.a21, a22 = o.a22, ox = o.ox, oy = o.oy;
  const uint32_t key = o.key;
  const int32_t px = o.px, py = o.py;
  const float ipx = o.ipx, ipy = o.ipy;
  // The lattice coordinates first, in their own loop: the noise loop below
  // then needs fewer live constants (AVX2 has 16 vector registers).
  float xs[kChunk], ys[kChunk];
  for (int i = 0; i < n; ++i) {
    xs[i] = (a11 * u[i] + a12 * v[i]) + ox;
    ys[i] = (a21 * u[i] + a22 * v[i]) + oy;
  }
  if constexpr (kBasis == kBasisCellularF1 || kBasis == kBasisCellularF2F1) {
    float f2[kChunk];
    for (int i = 0; i < n; ++i) {
      const F12 f = cellular_noise<kPeriodic>(key, xs[i], ys[i], px, py, ipx, ipy);
      out[i] = f.f1;
      f2[i] = f.f2;
    }
    cellular_distances<kBasis == kBasisCellularF1>(n, out, f2, out);
  } else {
    for (int i = 0; i < n; ++i) {
      if constexpr (kBasis == kBasisValue)
        out[i] = value_noise<kPeriodic>(key, xs[i], ys[i], px, py, ipx, ipy);
      else if constexpr (kBasis == kBasisGradient)
        out[i] = gradient_noise<kPeriodic>(key, xs[i], ys[i], px, py, ipx, ipy);
      else
        out[i] = simplex_noise(key, xs[i], ys[i]);  // periodic simplex is refused by validate_fbm
    }
  }
}

template <int kIsa, bool kPeriodic>
FT_INLINE void noise_row(int basis, const Octave& o, int n, const float* u, const float* v, bool v_const,
                         float* out) {
  switch (basis) {
    case kBasisValue: return basis_row<kIsa, kBasisValue, kPeriodic>(o, n, u, v, v_const, out);
    case kBasisGradient: return basis_row<kIsa, kBasisGradient, kPeriodic>(o, n, u, v, v_const, out);
    case kBasisSimplex: return basis_row<kIsa, kBasisSimplex, kPeriodic>(o, n, u, v, v_const, out);
    case kBasisCellularF1: return basis_row<kIsa, kBasisCellularF1, kPeriodic>(o, n, u, v, v_const, out);
    default: return basis_row<kIsa, kBasisCellularF2F1, kPeriodic>(o, n, u, v, v_const, out);
  }
}

// The octave loop, the same for every variant: one noise call per octave,
// then the variant's way of adding it in (Musgrave's formulations, with
// a_i = gain^i in place of f_i^-H).
template <int kIsa, bool kPeriodic>
FT_INLINE void octave_loop(const std::vector<Octave>& octs, int basis, int variant, float offset, int n,
                           const float* u, const float* v, bool v_const, float* sum) {
  if constexpr (kSimdRows<kIsa, kPeriodic>) {
    if (variant == kFbmStandard && basis <= kBasisSimplex) {  // the octave sum fused into the rows
      for (size_t k = 0; k < octs.size(); ++k)
        simd_noise_row<kIsa>(basis, octs[k], n, u, v, v_const, k == 0 ? kFirst : kAdd,
                             octs[k].amp, sum);
      return;
    }
  }
  float noise[kChunk], weight[kChunk];
  for (size_t k = 0; k < octs.size(); ++k) {
    const Octave& o = octs[k];
    noise_row<kIsa, kPeriodic>(basis, o, n, u, v, v_const, noise);
    const float a = o.amp;
    const bool first = k == 0;
    add_octave(variant, first, a, offset, n, noise, weight, sum);
  }
}

template <int kIsa, bool kPeriodic>
FT_INLINE void chunk_body(const Plan& p, int n, float* u, float* v, float* out) {
  const bool warped = !p.warp_x.empty();
  if (warped) {
    // The warp pass: displace the coordinates, then run the octaves on them.
    float wx[kChunk], wy[kChunk];
    octave_loop<kIsa, kPeriodic>(p.warp_x, kBasisGradient, kFbmStandard, 0.0f, n, u, v, true, wx);
    octave_loop<kIsa, kPeriodic>(p.warp_y, kBasisGradient, kFbmStandard, 0.0f, n, u, v, true, wy);
    for (int i = 0; i < n; ++i) {
      u[i] = u[i] + p.warp_u * wx[i];
      v[i] = v[i] + p.warp_v * wy[i];
    }
  }
  octave_loop<kIsa, kPeriodic>(p.octaves, p.basis, p.variant, p.offset, n, u, v, !warped, out);
  for (int i = 0; i < n; ++i) out[i] = out[i] * p.scale;
}

// Samples [xb, xb + count) of row y of a width x height terrain: normalised
// coordinates (from the global index alone, so a window gets the bits of the
// whole), then the octaves.
template <int kIsa>
FT_INLINE void row_body(const Plan& p, int64_t width, int64_t height, int64_t y, int64_t xb, int32_t count,
                        float* row) {
  alignas(32) float u[kChunk], v[kChunk];
  const float inv_w = 1.0f / float(width);
  const float vy = p.periodic ? float(y) / float(height) : float(y) * inv_w;
  for (int32_t x0 = 0; x0 < count; x0 += kChunk) {
    const int n = std::min<int32_t>(kChunk, count - x0);
    for (int i = 0; i < n; ++i) {
      u[i] = float(xb + x0 + i) * inv_w;
      v[i] = vy;
    }
    if (p.periodic)
      chunk_body<kIsa, true>(p, n, u, v, row + x0);
    else
      chunk_body<kIsa, false>(p, n, u, v, row + x0);
  }
}
#undef FT_INLINE

// Runtime dispatch: the same source compiled three times (AVX-512 with
// 512-bit vectors, AVX2, the x86-64 baseline). Hand-rolled rather than
// target_clones so a test can force a path and compare bits.
[[gnu::flatten]] __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq,prefer-vector-width=512"))) void
row_avx512(const Plan& p, int64_t w, int64_t h, int64_t y, int64_t xb, int32_t n, float* row) {
  row_body<kIsaAvx512>(p, w, h, y, xb, n, row);
}
[[gnu::flatten]] __attribute__((target("avx2"))) void row_avx2(const Plan& p, int64_t w, int64_t h, int64_t y,
                                                               int64_t xb, int32_t n, float* row) {
  row_body<kIsaAvx2>(p, w, h, y, xb, n, row);
}
[[gnu::flatten]] void row_baseline(const Plan& p, int64_t w, int64_t h, int64_t y, int64_t xb, int32_t n,
                                   float* row) {
  row_body<kIsaBaseline>(p, w, h, y, xb, n, row);
}

std::atomic<SimdPath> g_path{SimdPath::kAuto};

using RowFn = void (*)(const Plan&, int64_t, int64_t, int64_t, int64_t, int32_t, float*);
// The fastest path the CPU has (and FT_DISPATCH allows: ft::detail::dispatch_path),
// capped by set_simd_path.
RowFn pick_row_fn() {
  const SimdPath cap = g_path.load();
  if (cap == SimdPath::kBaseline) return row_baseline;
  const std::string_view best = ft::detail::dispatch_path();
  if (best == "avx512" && cap == SimdPath::kAuto) return row_avx512;
  if (best != "baseline") return row_avx2;
  return row_baseline;
}

// The largest |lattice coordinate| any octave can reach: |M| (|u| + |v|) + origin.
double max_lattice_coordinate(const FbmConfig& c) {
  const double umax = 1.0 + c.warp / c.frequency;
  const double vmax = (c.periodic ? 1.0 : double(c.height) / double(c.width)) + c.warp / c.frequency;
  const double aspect = c.periodic ? double(c.height) / double(c.width) : 1.0;
  const double f = c.frequency * std::pow(c.lacunarity, c.octaves - 1) * std::max(1.0, aspect) + 1.0;
  return f * (umax + vmax) + 256.0;
}

}  // namespace

double fbm_height_bound(const FbmConfig& c, double* unscaled) {
  const double nb = c.basis == kBasisCellularF1 || c.basis == kBasisCellularF2F1 ? 3.0 : 1.0;
  const double off = std::fabs(c.offset), gain = effective_gain(c);
  double amp = 1, amp_sum = 0, sum = 0, weight = 0;
  for (int k = 0; k < c.octaves; ++k, amp *= gain) {
    amp_sum += amp;
    switch (c.variant) {
      case kFbmStandard: sum += amp * nb; break;
      // s = (offset - |n|)^2 times a weight clamped to [0, 1].
      case kFbmRidged: sum += amp * (off + nb) * (off + nb); break;
      case kFbmHybrid: {
        // s = (n + offset) a; the weight min(w, 1) is at most 1 above and
        // unbounded below, so |w| <= max(1, |previous weight|).
        const double s = (nb + off) * amp;
        const double w = k == 0 ? 1.0 : std::max(1.0, weight);
        sum += w * s;
        weight = w * s;
        break;
      }
      default:  // hetero: sum_0 = offset + n, then sum *= 1 + (n + offset) a
        sum = k == 0 ? off + nb : sum * (1 + (nb + off) * amp);
        break;
    }
  }
  if (unscaled) *unscaled = sum;
  const bool bounded = c.variant == kFbmStandard || c.variant == kFbmRidged;
  return bounded ? sum / amp_sum : sum;
}

double effective_gain(const FbmConfig& c) {
  return c.gain > 0 ? c.gain : std::pow(c.lacunarity, -c.hurst);
}

void validate_fbm(const FbmConfig& c, int64_t max_side) {
  check_int_range("width", c.width, 2, max_side);
  check_int_range("height", c.height, 2, max_side);
  detail::validate_octave_fields(c);
  check_finite("rotation", c.rotation);
  check_range("warp", c.warp, 0.0, kMaxWarp);
  if (c.periodic && c.basis == kBasisSimplex)
    invalid("periodic fbm is available for the value, gradient and cellular bases, not simplex "
            "(its skewed lattice does not tile a rectangle)");
  const double m = max_lattice_coordinate(c);
  if (!(m <= kMaxLatticeCoordinate))
    invalid("the finest octave is beyond float resolution: frequency " + format_number(c.frequency) +
            " x lacunarity " + format_number(c.lacunarity) + "^(octaves - 1 = " + std::to_string(c.octaves - 1) +
            ") reaches lattice coordinate " + format_number(std::round(m)) + ", more than " +
            format_number(kMaxLatticeCoordinate) + "; use fewer octaves, a smaller lacunarity or frequency");
}

Heightfield fbm(const FbmConfig& c) {
  validate_fbm(c);
  return fbm_window(c, 0, 0, int32_t(c.width), int32_t(c.height));
}

Heightfield fbm_window(const FbmConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h) {
  Heightfield hf(w, h);
  fbm_window_into(c, x0, y0, w, h, hf.data());
  return hf;
}

void fbm_window_into(const FbmConfig& c, int64_t x0, int64_t y0, int32_t w, int32_t h, float* out) {
  const Plan plan = make_plan(c);
  const RowFn row_fn = pick_row_fn();
  // Rows handed out dynamically in one parallel region (barriers per band
  // cost dearly when the cores are shared); the calling thread reports.
  for_rows(h, c.threads, c.progress, [&](int64_t y) {
    row_fn(plan, c.width, c.height, y0 + y, x0, w, out + size_t(y) * size_t(w));
  });
}

namespace detail {
void set_simd_path(SimdPath path) { g_path.store(path); }
const char* active_simd_path() {
  const RowFn f = pick_row_fn();
  return f == row_avx512 ? "avx512" : f == row_avx2 ? "avx2" : "baseline";
}
}  // namespace detail

}  // namespace ft::noise
