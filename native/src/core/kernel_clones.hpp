// FT_KERNEL_CLONES: a hot loop built in several instruction sets.
#pragma once

// A kernel built in x86-64-v4 (AVX-512), AVX2 and portable versions, the
// best chosen at load time (GCC). Clang refuses clones of a template or of a
// noinline function, so its builds (the fuzzers') keep the portable one.
#if defined(__clang__)
#define FT_KERNEL_CLONES
#else
#define FT_KERNEL_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#endif
