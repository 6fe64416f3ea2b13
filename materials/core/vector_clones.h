#pragma once
// OCHRE_VECTOR_CLONES marks a function whose loops or straight-line arithmetic the compiler vectorizes
// (a loop over a path's wavelengths, the eight corners of a noise cell): GCC builds it twice, for AVX2
// (eight floats per instruction) and for baseline x86-64 (four), and picks one when the program starts.
// The two give the same bits: the same IEEE single-precision operations in the same order, lane by lane
// (no fused multiply-add: AVX2 does not imply FMA, and ISO C++ mode does not contract). Flattened:
// everything the function calls is inlined into each copy, so the clone's instructions reach it too.

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define OCHRE_VECTOR_CLONES [[gnu::flatten, gnu::target_clones("avx2", "default")]]
#else
#define OCHRE_VECTOR_CLONES [[gnu::flatten]]
#endif
