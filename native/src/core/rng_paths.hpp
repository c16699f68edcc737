// SPDX-License-Identifier: GPL-3.0-or-later
// The dispatch paths of gaussian_fill and uniform_fill (rng.hpp), internal
// to core/: rng.cpp holds the baseline and AVX2 paths and picks one at run
// time; rng_avx512.cpp holds the AVX-512 path. Every path gives the same bits.
#pragma once

#include <cstddef>
#include <cstdint>

#include "core/rng.hpp"

namespace ft::detail {

// Only where the CPU has AVX-512 F, BW, DQ and VL (cpu_has_avx512()).
void gaussian_fill_avx512(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out);
void uniform_fill_avx512(uint64_t seed, const Counter& c, uint64_t first, size_t n, float* out);

}  // namespace ft::detail
