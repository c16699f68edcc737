// SPDX-License-Identifier: GPL-3.0-or-later
// For the files that hold AVX-512 kernels (built into any x86-64 library and
// called only where the CPU has AVX-512: see their dispatchers).
#pragma once

// gcc 12 warns inside its own AVX-512 headers (the _mm512_undefined_*
// placeholders of unmasked intrinsics) once they are inlined into a kernel.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

// A kernel's helpers: compiled for AVX-512 F/VL/BW/DQ, always inlined into it.
#define FT_AVX512 __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq"), always_inline)) inline
