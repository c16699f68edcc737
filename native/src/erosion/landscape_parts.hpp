// SPDX-License-Identifier: GPL-3.0-or-later
// The parts of the landscape model that its run (landscape.cpp) and its
// coarse-to-fine windows (landscape_window.cpp) share.
#pragma once

#include <cstdint>
#include <vector>

#include "core/progress.hpp"
#include "erosion/d8_grid.hpp"
#include "erosion/erosion.hpp"

namespace ft::erosion {

// Bilinear sample of a w x h grid at fractional (fx, fy), clamped or wrapped.
float bilinear(const float* v, int32_t w, int32_t h, double fx, double fy, bool wrap);

// `from` (grid a) sampled at every node of grid b: both span the same
// terrain, corner to corner (bounded) or over one period (periodic).
std::vector<float> resample(const float* from, const D8Grid& a, const D8Grid& b);

// z averaged over (2r + 1)^2 cells around each cell (clamped at a bounded
// grid's edges, wrapped on a periodic one).
std::vector<float> box_mean(const float* z, const D8Grid& g, int32_t r);

// A deposit of mean depth d on a model cell laid on the texture the model
// does not see (see landscape.cpp).
float bury(float z, float seen, double sd, double d, float erodible);

// Steps of a run of `years` on grid g: between the model's least and `most`.
int32_t steps_for(const D8Grid& g, const ErosionConfig& c, double years, int32_t most);
// The most steps of a detail run.
inline constexpr int32_t kMaxDetailSteps = 3;

// The model's run on its own grid g (talus on, creep on z): z in place for
// `years` in `steps` steps, the mask and rain map (null: 1) on g; `crept`
// (null, or g.size() values) adds each cell's change by creep; `budget`
// (may be null) adds the run's volumes.
void model_run(const D8Grid& g, const ErosionConfig& c, const float* mask, const float* rain, MassBudget* budget,
               float* crept, float* z, double years, int32_t steps, const Progress& progress);

}  // namespace ft::erosion
