// Four floats in one SSE register (GCC/Clang vector extension), for the delegate's inner
// loops: the compilers keep these in registers, where plain float arrays of the same loops
// were vectorized poorly (3x slower in the relighting engine's weighted sum).
#pragma once

#include <cstring>

namespace opal {

using Float4 = float __attribute__((vector_size(16)));

inline Float4 load4(const float* p) {
    Float4 v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

inline void store4(float* p, Float4 v) { std::memcpy(p, &v, sizeof v); }

}  // namespace opal
