// XXH64 (Yann Collet's xxHash, 64-bit variant, seed 0 by default), implemented from the
// published specification (github.com/Cyan4973/xxHash, doc/xxhash_spec.md). Opal uses it
// as the checksum of sidecar headers, chunk tables and chunk bytes. zstd bundles XXH64 but
// does not export it, so Opal carries its own; tests check it against the specification's
// values and against the content checksum zstd writes into its frames.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace opal {

// Incremental XXH64: update() any number of times with consecutive pieces of the input,
// then digest(). The result does not depend on how the input is split into pieces.
class Xxh64 {
public:
    explicit Xxh64(std::uint64_t seed = 0);

    void update(std::span<const std::byte> bytes);
    std::uint64_t digest() const;

private:
    void consumeStripe(const std::byte* stripe);

    std::array<std::uint64_t, 4> acc_;
    std::uint64_t seed_;
    std::uint64_t totalLength_ = 0;
    std::array<std::byte, 32> pending_{};  // the start of an incomplete 32-byte stripe
    std::size_t pendingLength_ = 0;
};

std::uint64_t xxh64(std::span<const std::byte> bytes, std::uint64_t seed = 0);

}  // namespace opal
