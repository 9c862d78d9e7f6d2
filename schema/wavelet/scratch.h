// Per-thread scratch memory for the wavelet kernels. The transforms run in the inner
// loop of a bake and once per frame, so they must not allocate per call; a buffer that
// grows once per thread (and per element type) is the only state they keep. Internal to
// schema/wavelet: a caller must not hold the span across another wavelet call on the
// same thread.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace opal::wavelet_detail {

template <typename T>
std::span<T> threadScratch(std::size_t count) {
    thread_local std::vector<T> buffer;
    if (buffer.size() < count) buffer.resize(count);
    return {buffer.data(), count};
}

}  // namespace opal::wavelet_detail
