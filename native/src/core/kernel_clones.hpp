// SPDX-License-Identifier: GPL-3.0-or-later
// FT_KERNEL_CLONES: a hot loop built in several instruction sets.
#pragma once

// A kernel built in x86-64-v4 (AVX-512), AVX2 and portable versions, the
// best chosen at load time (GCC). Clang refuses clones of a template or of a
// noinline function, so its builds (the fuzzers') keep the portable one; so
// does Windows, whose DLLs have no ifunc, the ELF feature the clones are
// chosen through. Every version gives the same bits (-ffp-contract=off).
// FT_KERNEL_CLONES_AVX2: the same with AVX2 and portable versions only.
#if defined(__clang__) || defined(_WIN32)
#define FT_KERNEL_CLONES
#define FT_KERNEL_CLONES_AVX2
#else
#define FT_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#define FT_KERNEL_CLONES_AVX2 __attribute__((target_clones("avx2", "default")))
#endif
