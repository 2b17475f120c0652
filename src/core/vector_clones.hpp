#pragma once
// SD_VECTOR_CLONES before a function that holds a vectorised loop: GCC builds it twice, for
// AVX2 (four doubles a lane) and for the baseline x86-64 SSE2 (two), and picks one when the
// program starts. The two give bit-identical results: the loops do element-wise IEEE
// arithmetic and comparisons only, and -ffp-contract=off keeps multiply-adds apart (AVX2
// does not even imply FMA). So a design scores the same on every x86-64 machine, only faster
// where AVX2 is there. GCC only: clang 14 (the sanitizer and fuzz builds) emits a member
// function's clones but not the symbol that calls pick one, so the link fails.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define SD_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SD_VECTOR_CLONES
#endif
