// Explicit little-endian encoding of fixed-width scalars, independent of the host's byte
// order and of struct layout: every on-disk field of an Opal container goes through here
// (or, for arrays, through ChunkSink/ChunkSource, which assume a little-endian host).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace opal::le {

template <class U>
void put(std::vector<std::byte>& out, U value) {
    static_assert(std::is_unsigned_v<U>);
    for (std::size_t i = 0; i < sizeof(U); ++i)
        out.push_back(static_cast<std::byte>((value >> (8 * i)) & 0xFFu));
}

template <class U>
U get(std::span<const std::byte> in, std::size_t offset) {
    static_assert(std::is_unsigned_v<U>);
    U value = 0;
    for (std::size_t i = sizeof(U); i-- > 0;)
        value = static_cast<U>((value << 8) | std::to_integer<U>(in[offset + i]));
    return value;
}

inline void putF64(std::vector<std::byte>& out, double v) { put(out, std::bit_cast<std::uint64_t>(v)); }
inline double getF64(std::span<const std::byte> in, std::size_t offset) {
    return std::bit_cast<double>(get<std::uint64_t>(in, offset));
}

}  // namespace opal::le
