#include "schema/asset/xxhash64.h"

#include "schema/error.h"

#include <xxhash.h>

#include <new>

namespace opal {

void Xxh64::FreeState::operator()(XXH64_state_s* state) const { XXH64_freeState(state); }

Xxh64::Xxh64(std::uint64_t seed) : state_(XXH64_createState()) {
    if (!state_) throw std::bad_alloc();
    if (XXH64_reset(state_.get(), seed) != XXH_OK) throw Error("XXH64: cannot reset the hash state");
}

void Xxh64::update(std::span<const std::byte> bytes) {
    if (XXH64_update(state_.get(), bytes.data(), bytes.size()) != XXH_OK)
        throw Error("XXH64: cannot hash " + std::to_string(bytes.size()) + " bytes");
}

std::uint64_t Xxh64::digest() const { return XXH64_digest(state_.get()); }

std::uint64_t xxh64(std::span<const std::byte> bytes, std::uint64_t seed) {
    return XXH64(bytes.data(), bytes.size(), seed);
}

}  // namespace opal
