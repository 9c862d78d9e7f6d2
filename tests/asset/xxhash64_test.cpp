// XXH64 against published values, against the checksum zstd itself writes into a frame
// (the low 32 bits of XXH64 with seed 0 of the frame's content), and against every
// checksum in a sidecar written by Opal's former, hand-written XXH64 (tests/asset/legacy):
// three independent truths.
#include "schema/asset/xxhash64.h"
#include "tests/asset/test_files.h"

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

// SIDECAR.md's layout, read here byte by byte rather than through the sidecar reader, so
// that each stored checksum is compared with the library's XXH64 of exactly its bytes.
TEST(Xxh64, VerifiesEveryChecksumOfASidecarWrittenBeforeOpalUsedTheLibrary) {
    const std::vector<std::byte> file =
        test::readBytes(std::filesystem::path(OPAL_SOURCE_DIR) / "tests/asset/legacy/candle.opal");
    ASSERT_GE(file.size(), 64u);
    const std::span<const std::byte> bytes(file);
    EXPECT_EQ(xxh64(bytes.first(56)), test::getU64(file, 56)) << "header";
    const std::uint64_t tableOffset = test::getU64(file, 24);
    ASSERT_LE(tableOffset, file.size());
    EXPECT_EQ(xxh64(bytes.subspan(tableOffset)), test::getU64(file, 40)) << "chunk table";
    const std::size_t chunks = (file.size() - tableOffset) / 48;
    ASSERT_GE(chunks, 5u);
    for (std::size_t c = 0; c < chunks; ++c) {
        const std::size_t entry = tableOffset + 48 * c;
        const std::string tag(reinterpret_cast<const char*>(&file[entry]), 4);
        const auto codec = std::to_integer<int>(file[entry + 4]);
        const std::uint64_t offset = test::getU64(file, entry + 8), stored = test::getU64(file, entry + 16);
        const std::uint64_t raw = test::getU64(file, entry + 24);
        ASSERT_LE(offset + stored, tableOffset) << tag;
        const std::span<const std::byte> storedBytes = bytes.subspan(offset, stored);
        EXPECT_EQ(xxh64(storedBytes), test::getU64(file, entry + 32)) << tag << " stored bytes";
        std::vector<std::byte> rawBytes(storedBytes.begin(), storedBytes.end());
        if (codec == 1) {
            rawBytes.resize(raw);
            ASSERT_EQ(ZSTD_decompress(rawBytes.data(), raw, storedBytes.data(), stored), raw) << tag;
        }
        EXPECT_EQ(xxh64(rawBytes), test::getU64(file, entry + 40)) << tag << " raw bytes";
    }
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
