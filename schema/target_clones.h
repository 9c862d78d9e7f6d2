// OPAL_TARGET_CLONES("avx2", "default"): GCC compiles the function once per listed target
// and picks one when the program loads, so that a build for baseline x86-64 still runs its
// inner loops with the wider instructions of the machine it runs on. Clang cannot clone
// templates yet (the fuzz targets' build), so under clang the function is compiled once,
// for the baseline.
#pragma once

#if defined(__clang__) || !defined(__x86_64__)
#define OPAL_TARGET_CLONES(...)
#else
#define OPAL_TARGET_CLONES(...) __attribute__((target_clones(__VA_ARGS__)))
#endif
