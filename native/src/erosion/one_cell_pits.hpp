// SPDX-License-Identifier: GPL-3.0-or-later
// One-cell pits of an eroded surface: a sample below all 8 of its
// neighbours is lifted to the lowest of them (issue 40). Lifted a float
// step above it, the lowest became the pit wherever it drained only
// through the lifted sample; at its height no sample is left below all its
// neighbours (a lifted sample and its lowest may remain a two-sample
// hollow). The landscape model keeps the rock's texture, and with it
// the texture's pits (1-1.6 % of the samples of a midpoint mountain): water
// ponded in thousands of one-sample holes that any outside D8 tool sees.
// Lakes (flat floors, several samples) are not one-cell pits and stay.
#pragma once

#include <cstdint>

namespace ft::erosion {

// The height a sample at z takes given its 8 neighbours' heights: z, or,
// when it stands below all of them, the lowest's, lifted by `erodible` (the erosion mask, 1: fully; 0: it stays).
float one_cell_pit_lifted(float z, const float (&neighbours)[8], float erodible);

// Lifts the one-cell pits of a w x h grid in place (all read before any is
// written, so the result does not depend on the order). The edge samples
// of a bounded grid stay (they are base levels); a periodic grid wraps.
// `stays` (null: none) marks samples that stay (the sea); `mask` (null: 1)
// the erosion mask.
void lift_one_cell_pits(float* z, int32_t w, int32_t h, bool periodic, const uint8_t* stays, const float* mask);

}  // namespace ft::erosion
