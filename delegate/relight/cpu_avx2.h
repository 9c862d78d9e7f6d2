// Whether this CPU runs the delegate's AVX2 kernels: AVX2, FMA and F16C (half-float
// conversion). F16C is read from CPUID leaf 1 (ECX bit 29) because clang 14's
// __builtin_cpu_supports does not know "f16c". x86-64 only.
#pragma once

#include <cpuid.h>

namespace opal {

inline bool cpuHasAvx2FmaF16c() {
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    bool f16c = __get_cpuid(1, &eax, &ebx, &ecx, &edx) != 0 && (ecx & bit_F16C) != 0;
    return f16c && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

}  // namespace opal
