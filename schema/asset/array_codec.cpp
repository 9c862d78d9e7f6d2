#include "schema/asset/array_codec.h"

#include <Imath/half.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>

namespace opal {
namespace {

constexpr std::size_t kBlockValues = 16 * 1024;

// Plane k is byte k of each value's little-endian encoding, which on a little-endian host
// is byte k of its in-memory representation.
static_assert(std::endian::native == std::endian::little, "byte planes assume a little-endian host");

// Half planes: the scale exponent e with max |v| 2^-e in (2^14, 2^15], i.e.
// e = ceil(log2 max) - 15; 0 for an all-zero array. A maximum that rounds up to 2^15 2^e
// keeps the same e, which makes roundToHalfPlanes idempotent.
constexpr int kHalfTopExponent = 15;
constexpr int kMinHalfScale = -160, kMaxHalfScale = 111;  // 65504 2^111 < FLT_MAX

Imath::half toHalf(float v, int e) { return Imath::half(std::ldexp(v, -e)); }
float fromHalf(Imath::half h, int e) { return std::ldexp(float(h), e); }

// Byte planes of n Word-sized values, bitsOf(i) giving value i's bits: byte 0 of every
// value, then byte 1, ... in blocks of kBlockValues (bitsOf runs once per value and plane,
// so that no whole copy of the array is made).
template <typename Word, typename BitsOf>
void writeBytePlanes(ChunkSink& sink, std::size_t n, BitsOf&& bitsOf) {
    std::vector<std::byte> block(kBlockValues);
    for (std::size_t plane = 0; plane < sizeof(Word); ++plane) {
        for (std::size_t start = 0; start < n; start += kBlockValues) {
            const std::size_t count = std::min(kBlockValues, n - start);
            for (std::size_t i = 0; i < count; ++i) block[i] = std::byte((Word(bitsOf(start + i)) >> (8 * plane)) & 0xff);
            sink.write(std::span(block).first(count));
        }
    }
}

// The inverse, into out's bytes (byte k of a value is plane k on this little-endian host).
template <typename T>
void readBytePlanes(ChunkSource& source, std::span<T> out) {
    const std::span<std::byte> bytes = std::as_writable_bytes(out);
    std::vector<std::byte> block(kBlockValues);
    for (std::size_t plane = 0; plane < sizeof(T); ++plane) {
        for (std::size_t start = 0; start < out.size(); start += kBlockValues) {
            const std::size_t count = std::min(kBlockValues, out.size() - start);
            source.read(std::span(block).first(count));
            for (std::size_t i = 0; i < count; ++i) bytes[sizeof(T) * (start + i) + plane] = block[i];
        }
    }
}

}  // namespace

int halfScaleExponent(std::span<const float> values) {
    float largest = 0.0f;
    for (float v : values) largest = std::max(largest, std::abs(v));
    if (largest == 0.0f || !std::isfinite(largest)) return 0;
    int exponent = 0;
    const float mantissa = std::frexp(largest, &exponent);  // largest = mantissa 2^exponent, mantissa in [0.5, 1)
    const int ceilLog2 = mantissa == 0.5f ? exponent - 1 : exponent;
    return ceilLog2 - kHalfTopExponent;
}

void writeHalfPlanes(ChunkSink& sink, std::span<const float> values) {
    const int e = halfScaleExponent(values);
    sink.writeU32(std::bit_cast<std::uint32_t>(std::int32_t(e)));
    writeBytePlanes<std::uint16_t>(sink, values.size(), [&](std::size_t i) { return toHalf(values[i], e).bits(); });
}

std::vector<float> readHalfPlanes(ChunkSource& source, std::uint64_t count, std::string_view what) {
    const auto e = std::bit_cast<std::int32_t>(source.readU32());
    if (e < kMinHalfScale || e > kMaxHalfScale)
        source.fail(std::string(what) + ": half-float scale exponent " + std::to_string(e) + " is outside [" +
                    std::to_string(kMinHalfScale) + ", " + std::to_string(kMaxHalfScale) + "]");
    source.requireBytes(count, sizeof(std::uint16_t), what);
    std::vector<std::uint16_t> bits(static_cast<std::size_t>(count), 0);
    readBytePlanes(source, std::span(bits));
    std::vector<float> values(bits.size());
    for (std::size_t i = 0; i < bits.size(); ++i) {
        Imath::half h;
        h.setBits(bits[i]);
        if (!h.isFinite()) source.fail(std::string(what) + ": value " + std::to_string(i) + " is not finite");
        values[i] = fromHalf(h, e);
    }
    return values;
}

void roundToHalfPlanes(std::span<float> values) {
    const int e = halfScaleExponent(values);
    for (float& v : values) v = fromHalf(toHalf(v, e), e);
}

namespace {

std::uint64_t zigzag(std::int64_t v) { return (std::uint64_t(v) << 1) ^ std::uint64_t(v >> 63); }
std::int64_t unzigzag(std::uint64_t u) { return std::int64_t(u >> 1) ^ -std::int64_t(u & 1); }

std::size_t varintBytes(std::uint64_t u) {
    std::size_t n = 1;
    for (; u >= 0x80; u >>= 7) ++n;
    return n;
}

}  // namespace

void writeVarints(ChunkSink& sink, std::span<const std::int64_t> values) {
    std::uint64_t total = 0;
    for (std::int64_t v : values) total += varintBytes(zigzag(v));
    sink.writeU64(total);
    std::vector<std::byte> block;
    block.reserve(kBlockValues + 10);
    for (std::int64_t v : values) {
        for (std::uint64_t u = zigzag(v);; u >>= 7) {
            const bool more = u >= 0x80;
            block.push_back(std::byte((u & 0x7f) | (more ? 0x80 : 0)));
            if (!more) break;
        }
        if (block.size() >= kBlockValues) {
            sink.write(block);
            block.clear();
        }
    }
    sink.write(block);
}

std::vector<std::int64_t> readVarints(ChunkSource& source, std::uint64_t count, std::string_view what) {
    const std::uint64_t total = source.readU64();
    source.requireBytes(total, 1, what);
    if (total < count)
        source.fail(std::string(what) + ": " + std::to_string(count) + " values cannot fit in " +
                    std::to_string(total) + " bytes");
    std::vector<std::byte> bytes(static_cast<std::size_t>(total));
    source.read(bytes);
    std::vector<std::int64_t> values;
    values.reserve(static_cast<std::size_t>(count));
    std::size_t at = 0;
    while (values.size() < count) {
        std::uint64_t u = 0;
        for (int shift = 0;; shift += 7) {
            if (at == bytes.size())
                source.fail(std::string(what) + ": the bytes end inside value " + std::to_string(values.size()));
            const auto b = std::uint64_t(bytes[at++]);
            if (shift == 63 && b > 1)
                source.fail(std::string(what) + ": value " + std::to_string(values.size()) + " exceeds 64 bits");
            u |= (b & 0x7f) << shift;
            if (!(b & 0x80)) break;
        }
        values.push_back(unzigzag(u));
    }
    if (at != bytes.size())
        source.fail(std::string(what) + ": " + std::to_string(bytes.size() - at) + " bytes left after " +
                    std::to_string(count) + " values");
    return values;
}

void writeFloatPlanes(ChunkSink& sink, std::span<const float> values) {
    writeBytePlanes<std::uint32_t>(sink, values.size(), [&](std::size_t i) { return std::bit_cast<std::uint32_t>(values[i]); });
}

std::vector<float> readFloatPlanes(ChunkSource& source, std::uint64_t count, std::string_view what) {
    source.requireBytes(count, sizeof(float), what);
    std::vector<float> values(static_cast<std::size_t>(count));
    readBytePlanes(source, std::span(values));
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
