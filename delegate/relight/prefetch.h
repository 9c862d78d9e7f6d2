// A software prefetch for the relighting kernels' streamed arrays (docs/ARCHITECTURE.md#relighting).
// On the machines Opal is measured on, the hardware's prefetchers alone left the transfer
// product and the dome's vector sums waiting on their sequential reads (measurements beside
// each use: transfer_product.cpp, environment_vectors.cpp); a hint a fixed distance ahead of
// the element being read removed most of that wait.
#pragma once

#include <cstddef>
#include <cstdint>

namespace opal {

// A hint to fetch the cache line `bytes` past `at`. Past the end of an array it fetches
// nothing useful and faults nothing (a prefetch never faults); the address is formed as an
// integer, so no pointer beyond the array is formed.
inline void prefetchAhead(const void* at, std::size_t bytes) {
    __builtin_prefetch(reinterpret_cast<const void*>(reinterpret_cast<std::uintptr_t>(at) + bytes));
}

// Every 64-byte line of the `length` bytes that start `bytes` past `at`: a row of a
// per-sample array some rows ahead.
inline void prefetchRangeAhead(const void* at, std::size_t bytes, std::size_t length) {
    for (std::size_t b = 0; b < length; b += 64) prefetchAhead(at, bytes + b);
}

}  // namespace opal
