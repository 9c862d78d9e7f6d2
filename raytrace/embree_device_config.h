// The configuration string every Opal Embree device is made with (rtcNewDevice). Embree
// picks its kernels (SSE2, SSE4.2, AVX, AVX2, AVX-512) from the processor at run time, so a
// bake's visibility could depend on the node; $OPAL_EMBREE_ISA caps them (Embree's
// `max_isa`: sse2, sse4.2, avx, avx2 or avx512), which is how a test runs the baseline
// x86-64 kernels on a newer processor.
#pragma once

#include <string>

namespace opal {

inline constexpr const char* kEmbreeIsaVariable = "OPAL_EMBREE_ISA";

// "max_isa=ISA" when $OPAL_EMBREE_ISA is set, else empty (Embree's defaults). Throws
// opal::Error naming the variable for a value Embree does not know (it would silently
// take SSE2 for it).
std::string embreeDeviceConfig();

}  // namespace opal
