#include "schema/asset/array_codec.h"

#include <algorithm>
#include <bit>

namespace opal {
namespace {

constexpr std::size_t kBlockValues = 16 * 1024;

// Plane k is byte k of each value's little-endian encoding, which on a little-endian host
// is byte k of its in-memory representation.
static_assert(std::endian::native == std::endian::little, "byte planes assume a little-endian host");

}  // namespace

void writeFloatPlanes(ChunkSink& sink, std::span<const float> values) {
    auto bytes = std::as_bytes(values);
    std::vector<std::byte> block(kBlockValues);
    for (std::size_t plane = 0; plane < 4; ++plane) {
        for (std::size_t start = 0; start < values.size(); start += kBlockValues) {
            std::size_t n = std::min(kBlockValues, values.size() - start);
            for (std::size_t i = 0; i < n; ++i) block[i] = bytes[4 * (start + i) + plane];
            sink.write(std::span(block).first(n));
        }
    }
}

std::vector<float> readFloatPlanes(ChunkSource& source, std::uint64_t count, std::string_view what) {
    source.requireBytes(count, sizeof(float), what);
    std::vector<float> values(static_cast<std::size_t>(count));
    auto bytes = std::as_writable_bytes(std::span(values));
    std::vector<std::byte> block(kBlockValues);
    for (std::size_t plane = 0; plane < 4; ++plane) {
        for (std::size_t start = 0; start < values.size(); start += kBlockValues) {
            std::size_t n = std::min(kBlockValues, values.size() - start);
            source.read(std::span(block).first(n));
            for (std::size_t i = 0; i < n; ++i) bytes[4 * (start + i) + plane] = block[i];
        }
    }
    return values;
}

template <class Offset>
void writeRowDeltas(ChunkSink& sink, std::span<const Offset> offsets, std::span<const std::uint32_t> indices) {
    std::vector<std::uint32_t> block;
    block.reserve(kBlockValues);
    for (std::size_t row = 0; row + 1 < offsets.size(); ++row) {
        std::uint32_t previous = 0;
        for (std::size_t j = offsets[row]; j < offsets[row + 1]; ++j) {
            block.push_back(indices[j] - previous);
            previous = indices[j];
            if (block.size() == kBlockValues) {
                sink.writeArray<std::uint32_t>(block);
                block.clear();
            }
        }
    }
    sink.writeArray<std::uint32_t>(block);
}

template <class Offset>
std::vector<std::uint32_t> readRowDeltas(ChunkSource& source, std::span<const Offset> offsets,
                                         std::string_view what) {
    std::vector<std::uint32_t> indices = source.readArray<std::uint32_t>(offsets.empty() ? 0 : offsets.back(), what);
    for (std::size_t row = 0; row + 1 < offsets.size(); ++row) {
        std::uint32_t previous = 0;
        for (std::size_t j = offsets[row]; j < offsets[row + 1]; ++j) previous = indices[j] += previous;
    }
    return indices;
}

template void writeRowDeltas<std::uint32_t>(ChunkSink&, std::span<const std::uint32_t>, std::span<const std::uint32_t>);
template void writeRowDeltas<std::uint64_t>(ChunkSink&, std::span<const std::uint64_t>, std::span<const std::uint32_t>);
template std::vector<std::uint32_t> readRowDeltas<std::uint32_t>(ChunkSource&, std::span<const std::uint32_t>, std::string_view);
template std::vector<std::uint32_t> readRowDeltas<std::uint64_t>(ChunkSource&, std::span<const std::uint64_t>, std::string_view);

}  // namespace opal
