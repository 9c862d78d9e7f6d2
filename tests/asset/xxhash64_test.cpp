// XXH64 against published values and against the checksum zstd itself writes into a
// frame (the low 32 bits of XXH64 with seed 0 of the frame's content): two independent
// truths.
#include "schema/asset/xxhash64.h"

#include <gtest/gtest.h>
#include <zstd.h>

#include <cstring>
#include <random>
#include <string_view>
#include <vector>

namespace opal {
namespace {

std::span<const std::byte> bytesOf(std::string_view s) { return std::as_bytes(std::span(s.data(), s.size())); }

std::vector<std::byte> randomBytes(std::size_t n, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<std::byte> b(n);
    for (auto& x : b) x = std::byte(rng() & 0xFF);
    return b;
}

// Reference values of the xxHash reference implementation (as quoted by many independent
// ports), covering the < 4, < 8, < 32 byte tails and the 32-byte stripe loop.
TEST(Xxh64, MatchesPublishedValues) {
    const std::string_view sentence = "Nobody inspects the spammish repetition";
    std::vector<std::byte> sequence(256);
    for (int i = 0; i < 256; ++i) sequence[i] = std::byte(i);
    EXPECT_EQ(xxh64(bytesOf("")), 0xEF46DB3751D8E999ull);
    EXPECT_EQ(xxh64(bytesOf("a")), 0xD24EC4F1A98C6E5Bull);
    EXPECT_EQ(xxh64(bytesOf("abc")), 0x44BC2CF5AD770999ull);
    EXPECT_EQ(xxh64(bytesOf(sentence)), 0xFBCEA83C8A378BF1ull);
    EXPECT_EQ(xxh64(sequence), 0x1FACBE8406CD904Bull);
    EXPECT_EQ(xxh64(bytesOf(""), 0x9E3779B1), 0xAC75FDA2929B17EFull);
    EXPECT_EQ(xxh64(bytesOf("abc"), 0x9E3779B1), 0x1318DF30094A85FDull);
    EXPECT_EQ(xxh64(bytesOf(sentence), 0x9E3779B1), 0x56DB22DD5B051147ull);
    EXPECT_EQ(xxh64(sequence, 0x9E3779B1), 0xD48195F45908996Cull);
}

TEST(Xxh64, AgreesWithZstdFrameChecksums) {
    ZSTD_CCtx* cctx = ZSTD_createCCtx();
    ZSTD_CCtx_setParameter(cctx, ZSTD_c_checksumFlag, 1);
    std::vector<std::size_t> lengths;
    for (std::size_t n = 0; n <= 200; ++n) lengths.push_back(n);
    for (std::size_t n : {1000u, 4096u, 65537u, 300001u}) lengths.push_back(n);
    for (std::size_t n : lengths) {
        std::vector<std::byte> data = randomBytes(n, static_cast<std::uint32_t>(n));
        std::vector<unsigned char> frame(ZSTD_compressBound(n));
        std::size_t size = ZSTD_compress2(cctx, frame.data(), frame.size(), data.data(), n);
        ASSERT_FALSE(ZSTD_isError(size));
        std::uint32_t zstdChecksum = 0;
        std::memcpy(&zstdChecksum, frame.data() + size - 4, 4);  // little-endian host
        EXPECT_EQ(zstdChecksum, static_cast<std::uint32_t>(xxh64(data))) << "length " << n;
    }
    ZSTD_freeCCtx(cctx);
}

TEST(Xxh64, IncrementalEqualsOneShotForEverySplit) {
    std::vector<std::byte> data = randomBytes(100, 7);
    std::uint64_t whole = xxh64(data);
    for (std::size_t a = 0; a <= data.size(); ++a) {
        for (std::size_t b = a; b <= data.size(); b += 7) {
            Xxh64 hash;
            hash.update(std::span(data).first(a));
            hash.update(std::span(data).subspan(a, b - a));
            hash.update(std::span(data).subspan(b));
            ASSERT_EQ(hash.digest(), whole) << "split at " << a << ", " << b;
        }
    }
}

}  // namespace
}  // namespace opal
