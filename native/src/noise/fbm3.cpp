// SPDX-License-Identifier: GPL-3.0-or-later
#include "noise/fbm3.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "core/error.hpp"
#include "core/rng.hpp"
#include "noise/basis3.hpp"
#include "noise/octave_sum.hpp"

namespace ft::noise {
namespace {

using namespace detail;

#define FT_INLINE [[gnu::always_inline]] inline

constexpr int kChunk = 256;

// noise(M p + o) of one octave for n points.
template <int kBasis>
FT_INLINE void basis_chunk(const Octave3& o, int n, const double* px, const double* py, const double* pz,
                           float* out) {
  const double* m = o.m;
  const uint32_t key = o.key;
  double xs[kChunk], ys[kChunk], zs[kChunk];
  for (int i = 0; i < n; ++i) {
    xs[i] = (m[0] * px[i] + m[1] * py[i] + m[2] * pz[i]) + o.o[0];
    ys[i] = (m[3] * px[i] + m[4] * py[i] + m[5] * pz[i]) + o.o[1];
    zs[i] = (m[6] * px[i] + m[7] * py[i] + m[8] * pz[i]) + o.o[2];
  }
  // The cells in double, then the noise in float and int32 only (arrays
  // per member: an array of Cell3 structs does not vectorise).
  int32_t ci[kChunk], cj[kChunk], ck[kChunk];
  float fx[kChunk], fy[kChunk], fz[kChunk];
  for (int i = 0; i < n; ++i) {
    const Cell3 c = kBasis == kBasisSimplex ? simplex_cell3(xs[i], ys[i], zs[i]) : cell3(xs[i], ys[i], zs[i]);
    ci[i] = c.i, cj[i] = c.j, ck[i] = c.k, fx[i] = c.fx, fy[i] = c.fy, fz[i] = c.fz;
  }
#define FT_CELL(i) Cell3{ci[i], cj[i], ck[i], fx[i], fy[i], fz[i]}
  if constexpr (kBasis == kBasisCellularF1 || kBasis == kBasisCellularF2F1) {
    float f2[kChunk];
    for (int i = 0; i < n; ++i) {
      const F12 f = cellular_noise3(key, FT_CELL(i));
      out[i] = f.f1;
      f2[i] = f.f2;
    }
    cellular_distances<kBasis == kBasisCellularF1>(n, out, f2, out);
  } else {
    for (int i = 0; i < n; ++i) {
      if constexpr (kBasis == kBasisValue)
        out[i] = value_noise3(key, FT_CELL(i));
      else if constexpr (kBasis == kBasisGradient)
        out[i] = gradient_noise3(key, FT_CELL(i));
      else
        out[i] = simplex_noise3(key, FT_CELL(i));
    }
  }
#undef FT_CELL
}

FT_INLINE void noise_chunk(int basis, const Octave3& o, int n, const double* x, const double* y, const double* z,
                           float* out) {
  switch (basis) {
    case kBasisValue: return basis_chunk<kBasisValue>(o, n, x, y, z, out);
    case kBasisGradient: return basis_chunk<kBasisGradient>(o, n, x, y, z, out);
    case kBasisSimplex: return basis_chunk<kBasisSimplex>(o, n, x, y, z, out);
    case kBasisCellularF1: return basis_chunk<kBasisCellularF1>(o, n, x, y, z, out);
    default: return basis_chunk<kBasisCellularF2F1>(o, n, x, y, z, out);
  }
}

FT_INLINE void evaluate_body(const SphereFbm& f, int64_t count, const double* x, const double* y, const double* z,
                             float* out) {
  float noise[kChunk], weight[kChunk];
  const std::vector<Octave3>& octs = f.octaves();
  for (int64_t b = 0; b < count; b += kChunk) {
    const int n = int(std::min<int64_t>(kChunk, count - b));
    float* sum = out + b;
    for (size_t k = 0; k < octs.size(); ++k) {
      noise_chunk(f.basis(), octs[k], n, x + b, y + b, z + b, noise);
      add_octave(f.variant(), k == 0, octs[k].amp, f.offset(), n, noise, weight, sum);
    }
    const float s = f.scale();
    for (int i = 0; i < n; ++i) sum[i] = sum[i] * s;
  }
}
#undef FT_INLINE

// The same source twice, as fbm.cpp does: AVX2 where the CPU has it, else the
// baseline; both give the same bits (-ffp-contract=off, no FMA contraction).
[[gnu::flatten]] __attribute__((target("avx2"))) void evaluate_avx2(const SphereFbm& f, int64_t n, const double* x,
                                                                      const double* y, const double* z, float* out) {
  evaluate_body(f, n, x, y, z, out);
}
[[gnu::flatten]] void evaluate_baseline(const SphereFbm& f, int64_t n, const double* x, const double* y,
                                        const double* z, float* out) {
  evaluate_body(f, n, x, y, z, out);
}

// A uniformly random rotation (Shoemake's unit quaternion from three
// uniforms), row-major, times the octave's frequency.
void rotation(const uint32_t* bits, double f, double* m) {
  const double u1 = bits_to_unit_open(bits[0]), u2 = bits_to_unit_open(bits[1]), u3 = bits_to_unit_open(bits[2]);
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1), t2 = 2 * std::numbers::pi * u2, t3 = 2 * std::numbers::pi * u3;
  const double w = a * std::sin(t2), x = a * std::cos(t2), y = b * std::sin(t3), z = b * std::cos(t3);
  const double r[9] = {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
                       2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
                       2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
  for (int i = 0; i < 9; ++i) m[i] = f * r[i];
}

double gain_of(const Fbm3Config& c) { return c.gain > 0 ? c.gain : std::pow(c.lacunarity, -c.hurst); }

FbmConfig as_flat(const Fbm3Config& c) {
  FbmConfig f;
  f.octaves = c.octaves;
  f.lacunarity = c.lacunarity;
  f.gain = c.gain;
  f.hurst = c.hurst;
  f.basis = c.basis;
  f.variant = c.variant;
  f.offset = c.offset;
  f.sigma = c.sigma;
  return f;
}

}  // namespace

void validate_fbm3(const Fbm3Config& c) {
  detail::validate_octave_fields(c);
  const double finest = c.frequency * std::pow(c.lacunarity, c.octaves - 1) + 256.0 + 1.0;
  if (!(finest <= kMaxLatticeCoordinate3))
    invalid("the finest octave is beyond the noise lattice's range: frequency " + format_number(c.frequency) +
            " x lacunarity " + format_number(c.lacunarity) + "^(octaves - 1 = " + std::to_string(c.octaves - 1) +
            ") is " + format_number(std::round(finest)) + " cells per radius, more than 2^30; use fewer octaves, "
            "a smaller lacunarity or frequency");
}

double fbm3_height_bound(const Fbm3Config& c) { return fbm_height_bound(as_flat(c)); }

SphereFbm::SphereFbm(const Fbm3Config& c) : basis_(c.basis), variant_(c.variant), offset_(float(c.offset)) {
  validate_fbm3(c);
  const double gain = gain_of(c);
  octaves_.resize(size_t(c.octaves));
  double f = c.frequency, a = 1.0, sum = 0.0;
  for (int i = 0; i < c.octaves; ++i, f *= c.lacunarity, a *= gain) {
    Octave3& o = octaves_[size_t(i)];
    // Octave i's numbers: block 0 (key, origin), block 1 (rotation) of the
    // planet stream's counter for octave i.
    const auto r0 = philox_block(c.seed, Counter{0, uint32_t(i), Stream::kPlanetNoise}, 0);
    const auto r1 = philox_block(c.seed, Counter{0, uint32_t(i), Stream::kPlanetNoise}, 1);
    o.key = r0.v[0];
    for (int k = 0; k < 3; ++k) o.o[k] = double(r0.v[k + 1] >> 8) * (256.0 / 16777216.0);
    rotation(r1.v, f, o.m);
    o.amp = float(a);
    sum += o.amp;
  }
  const bool bounded = c.variant == kFbmStandard || c.variant == kFbmRidged;
  scale_ = float(bounded ? c.sigma / sum : c.sigma);
}

void SphereFbm::evaluate(int64_t n, const double* x, const double* y, const double* z, float* out) const {
  if (std::strcmp(detail::active_simd_path(), "baseline") != 0)  // AVX2 where AVX-512 is, too
    evaluate_avx2(*this, n, x, y, z, out);
  else
    evaluate_baseline(*this, n, x, y, z, out);
}

float SphereFbm::at(double x, double y, double z) const {
  float out;
  evaluate(1, &x, &y, &z, &out);
  return out;
}

}  // namespace ft::noise
