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

// Whether Embree makes a device here, configured as every Opal device is: false where it
// refuses the processor (it needs SSE2 at least). What a renderer plugin's isSupported()
// asks. Throws opal::Error for a bad $OPAL_EMBREE_ISA (embreeDeviceConfig's), which no
// device could be made with.
bool embreeDeviceAvailable();

}  // namespace opal
