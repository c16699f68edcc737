// SPDX-License-Identifier: GPL-3.0-or-later
// Eroded surfaces drain (issue 40): no sample below all 8 neighbours after
// any preset at any size, on midpoint and fBm inputs (one_cell_pits.hpp).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "erosion/erosion.hpp"
#include "erosion/presets.hpp"
#include "test_terrains.hpp"

namespace ft::erosion {
namespace {

using test::default_mountain;
using test::fbm_terrain;

ErosionConfig preset_for(const std::string& id) {
  ErosionConfig c = erosion_preset(id);
  c.threads = 2;
  return c;
}

class EveryPreset : public ::testing::TestWithParam<std::string> {};
INSTANTIATE_TEST_SUITE_P(ErodedPits, EveryPreset, ::testing::ValuesIn(erosion_preset_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

// The share of interior samples below all 8 neighbours.
double pit_share(const Heightfield& hf) {
  const int32_t w = hf.width(), h = hf.height();
  const float* z = hf.data();
  int64_t pits = 0;
  for (int32_t y = 1; y < h - 1; ++y)
    for (int32_t x = 1; x < w - 1; ++x) {
      const float c = z[size_t(y) * w + x];
      bool below = true;
      for (int32_t dy = -1; dy <= 1 && below; ++dy)
        for (int32_t dx = -1; dx <= 1 && below; ++dx)
          if (dx || dy) below = c < z[size_t(y + dy) * w + x + dx];
      pits += below;
    }
  return double(pits) / (double(w - 2) * (h - 2));
}

TEST_P(EveryPreset, LeavesNoOneCellPits) {
  // Issue 40: at most 0.2 % of the interior below all 8 neighbours, on
  // midpoint and fBm inputs at every size (257^2 on its own grid, 65^2
  // resampled onto it, 1025^2 coarse to fine). The inputs hold 1.8-3.7 %, and the
  // detail run keeps the rock's texture with its pits (midpoint levels 9,
  // seed 3, Gentle Valleys: 1.4 %); lifted to their lowest neighbour, none
  // is left, so the bound (the issue's) has room for a rule that leaves a
  // few.
  for (const int32_t levels : {6, 8, 10}) {
    const int32_t size = (1 << levels) + 1;
    const Heightfield inputs[] = {default_mountain(levels, 3), fbm_terrain(size, 3)};
    for (int k = 0; k < 2; ++k) {
      const double in_share = pit_share(inputs[k]);
      const double share = pit_share(erode(inputs[k], preset_for(GetParam()), nullptr));
      std::printf("%-16s %-8s %4d^2: one-cell pits %.4f %% (input %.3f %%)\n", GetParam().c_str(),
                  k ? "fbm" : "midpoint", size, 100 * share, 100 * in_share);
      EXPECT_LE(share, 0.002) << GetParam() << (k ? " fbm " : " midpoint ") << size;
    }
  }
}

TEST_P(EveryPreset, LeavesNoOneCellPitsOnOtherSeeds) {
  // The same bound over more seeds (issue 40's property over seeds, sizes
  // and presets) at the two small sizes, where a run costs milliseconds: a
  // rule that held on seed 3 by chance would fail here. The bound is the
  // issue's, not a measured share (all seeds measured leave none).
  for (const int32_t levels : {6, 8})
    for (const uint64_t seed : {1, 2, 4}) {
      const int32_t size = (1 << levels) + 1;
      const Heightfield inputs[] = {default_mountain(levels, seed), fbm_terrain(size, seed)};
      for (int k = 0; k < 2; ++k) {
        const double share = pit_share(erode(inputs[k], preset_for(GetParam()), nullptr));
        EXPECT_LE(share, 0.002) << GetParam() << (k ? " fbm " : " midpoint ") << size << " seed " << seed;
      }
    }
}

}  // namespace
}  // namespace ft::erosion
