// SPDX-License-Identifier: GPL-3.0-or-later
// fBm on the unit sphere: the octave loop of fbm.hpp around the 3D bases of
// basis3.hpp, evaluated at unit vectors given in double precision.
//
//   t(p) = sum_i a_i noise(f_i R_i p + o_i),  f_i = frequency lacunarity^i,  a_i = gain^i
//
// p is a point of the unit sphere, so `frequency` counts base-octave cells
// per radius; R_i is a random rotation per octave (no octave's lattice lines
// up with another's or with the axes) and o_i a random origin in [0, 256)
// cells. The lattice coordinates are computed in double and split into a
// cell and a float offset inside it, so the finest octave keeps its detail
// up to 2^30 cells per radius (an Earth-radius planet at 2 m needs 2^22).
// The output is a function of p alone: no seams, no poles, and a patch of
// any layout has the bits of the whole.
#pragma once

#include <cstdint>
#include <vector>

#include "noise/fbm.hpp"

namespace ft::noise {

// The largest lattice coordinate the 3D bases take (basis3.hpp).
inline constexpr double kMaxLatticeCoordinate3 = 1073741824.0;  // 2^30

struct Fbm3Config {
  int32_t octaves = 12;       // 1..30
  double lacunarity = 2.0;    // > 1
  double gain = 0.0;          // (0, 1]; <= 0: lacunarity^-H
  double hurst = 0.8;         // used when gain <= 0
  int32_t basis = kBasisGradient;
  int32_t variant = kFbmStandard;
  double frequency = 1.5;     // base-octave cells per radius, > 0
  double offset = 1.0;        // ridged / hybrid / hetero offset
  double sigma = 1.0;         // output scale (standard and ridged: divided by sum a_i)
  uint64_t seed = 1;
};

// Throws ft::Error naming the field and its range (also when the finest
// octave passes kMaxLatticeCoordinate3).
void validate_fbm3(const Fbm3Config& c);
// The same bound as fbm_height_bound (|height| / sigma over every sample).
double fbm3_height_bound(const Fbm3Config& c);

struct Octave3 {
  double m[9];          // f_i R_i, row-major
  double o[3];          // origin in cells
  float amp = 1;
  uint32_t key = 0;
};

// The octaves of a config, made once and shared by every thread.
class SphereFbm {
 public:
  explicit SphereFbm(const Fbm3Config& c);  // validates
  // out[i] = the field at the unit vector (x[i], y[i], z[i]), i < n (any n).
  void evaluate(int64_t n, const double* x, const double* y, const double* z, float* out) const;
  float at(double x, double y, double z) const;

  const std::vector<Octave3>& octaves() const { return octaves_; }
  int32_t basis() const { return basis_; }
  int32_t variant() const { return variant_; }
  float offset() const { return offset_; }
  float scale() const { return scale_; }

 private:
  std::vector<Octave3> octaves_;
  int32_t basis_, variant_;
  float offset_, scale_;
};

}  // namespace ft::noise
