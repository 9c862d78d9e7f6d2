// XXH64 (Yann Collet's xxHash, 64-bit variant, seed 0 by default) from Debian's libxxhash
// (libxxhash-dev), in the terms the rest of Opal speaks: spans of bytes. Opal uses it as
// the checksum of sidecar headers, chunk tables and chunk bytes (SIDECAR.md). Tests check
// it against published values, against the content checksum zstd writes into its frames,
// and against a sidecar written before Opal used the library (tests/asset/legacy).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

struct XXH64_state_s;  // xxhash.h's streaming state, kept out of Opal's headers

namespace opal {

// Incremental XXH64: update() any number of times with consecutive pieces of the input,
// then digest(). The result does not depend on how the input is split into pieces.
class Xxh64 {
public:
    explicit Xxh64(std::uint64_t seed = 0);

    void update(std::span<const std::byte> bytes);
    std::uint64_t digest() const;

private:
    struct FreeState {
        void operator()(XXH64_state_s* state) const;
    };
    std::unique_ptr<XXH64_state_s, FreeState> state_;
};

std::uint64_t xxh64(std::span<const std::byte> bytes, std::uint64_t seed = 0);

}  // namespace opal
