#include "schema/asset/xxhash64.h"

#include <algorithm>
#include <bit>
#include <cstring>

namespace opal {
namespace {

constexpr std::uint64_t kPrime1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t kPrime2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::uint64_t kPrime3 = 0x165667B19E3779F9ull;
constexpr std::uint64_t kPrime4 = 0x85EBCA77C2B2AE63ull;
constexpr std::uint64_t kPrime5 = 0x27D4EB2F165667C5ull;

std::uint64_t loadLittleEndian(const std::byte* p, int bytes) {
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i) v = (v << 8) | std::to_integer<std::uint64_t>(p[i]);
    return v;
}

std::uint64_t round(std::uint64_t acc, std::uint64_t lane) {
    acc += lane * kPrime2;
    return std::rotl(acc, 31) * kPrime1;
}

std::uint64_t mergeAccumulator(std::uint64_t acc, std::uint64_t accN) {
    acc ^= round(0, accN);
    return acc * kPrime1 + kPrime4;
}

std::uint64_t converge(const std::array<std::uint64_t, 4>& a) {
    std::uint64_t acc = std::rotl(a[0], 1) + std::rotl(a[1], 7) + std::rotl(a[2], 12) +
                        std::rotl(a[3], 18);
    for (std::uint64_t accN : a) acc = mergeAccumulator(acc, accN);
    return acc;
}

// Step 5 of the specification: the last 0..31 bytes.
std::uint64_t consumeTail(std::uint64_t acc, const std::byte* p, std::size_t length) {
    for (; length >= 8; p += 8, length -= 8)
        acc = std::rotl(acc ^ round(0, loadLittleEndian(p, 8)), 27) * kPrime1 + kPrime4;
    if (length >= 4) {
        acc = std::rotl(acc ^ (loadLittleEndian(p, 4) * kPrime1), 23) * kPrime2 + kPrime3;
        p += 4;
        length -= 4;
    }
    for (; length > 0; ++p, --length)
        acc = std::rotl(acc ^ (std::to_integer<std::uint64_t>(*p) * kPrime5), 11) * kPrime1;
    return acc;
}

std::uint64_t avalanche(std::uint64_t acc) {
    acc ^= acc >> 33;
    acc *= kPrime2;
    acc ^= acc >> 29;
    acc *= kPrime3;
    acc ^= acc >> 32;
    return acc;
}

}  // namespace

Xxh64::Xxh64(std::uint64_t seed)
    : acc_{seed + kPrime1 + kPrime2, seed + kPrime2, seed, seed - kPrime1}, seed_(seed) {}

void Xxh64::consumeStripe(const std::byte* stripe) {
    for (int lane = 0; lane < 4; ++lane)
        acc_[lane] = round(acc_[lane], loadLittleEndian(stripe + 8 * lane, 8));
}

void Xxh64::update(std::span<const std::byte> bytes) {
    if (bytes.empty()) return;  // its data() may be null, which memcpy must not see
    totalLength_ += bytes.size();
    const std::byte* p = bytes.data();
    std::size_t left = bytes.size();
    if (pendingLength_ > 0) {
        std::size_t take = std::min(left, pending_.size() - pendingLength_);
        std::memcpy(pending_.data() + pendingLength_, p, take);
        pendingLength_ += take;
        p += take;
        left -= take;
        if (pendingLength_ < pending_.size()) return;
        consumeStripe(pending_.data());
        pendingLength_ = 0;
    }
    for (; left >= 32; p += 32, left -= 32) consumeStripe(p);
    if (left > 0) std::memcpy(pending_.data(), p, left);
    pendingLength_ = left;
}

std::uint64_t Xxh64::digest() const {
    std::uint64_t acc = totalLength_ >= 32 ? converge(acc_) : seed_ + kPrime5;
    acc += totalLength_;
    return avalanche(consumeTail(acc, pending_.data(), pendingLength_));
}

std::uint64_t xxh64(std::span<const std::byte> bytes, std::uint64_t seed) {
    Xxh64 hash(seed);
    hash.update(bytes);
    return hash.digest();
}

}  // namespace opal
