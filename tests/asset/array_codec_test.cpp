// Half planes against their stated precision (array_codec.h): every value within 2^-11
// relative of the original down to 2^-28 of the array's largest magnitude, within 2^-39
// of the largest below that; exact round trips of what roundToHalfPlanes gives; bad scales
// and non-finite halves rejected.
#include "schema/asset/array_codec.h"

#include "schema/asset/chunked_file.h"
#include "schema/error.h"
#include "tests/asset/test_files.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>

namespace opal {
namespace {
using test::errorOf;

const FileKind kCodecKind{"TEST", {1, 0}};

// Writes `values` as one chunk of half planes and reads them back.
std::vector<float> throughFile(const test::TempDir& dir, std::span<const float> values) {
    const auto path = dir / "h.opal";
    writeChunkedFile(path, kCodecKind, std::vector{ChunkProducer{"HALF", ChunkCodec::Zstd, true, [&](ChunkSink& s) {
                                                               writeHalfPlanes(s, values);
                                                           }}});
    ChunkedFileReader reader(path, kCodecKind);
    ChunkSource source = reader.open("HALF");
    std::vector<float> back = readHalfPlanes(source, values.size(), "values");
    source.finish();
    return back;
}

using test::bits;

// Magnitudes spread over 40 octaves below `largest`, random signs, a few exact zeros.
std::vector<float> spreadValues(std::size_t n, float largest, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> octave(-40.0f, 0.0f), sign(-1.0f, 1.0f);
    std::vector<float> v(n);
    for (float& x : v) x = std::copysign(largest * std::exp2(octave(rng)), sign(rng));
    v[0] = largest;
    v[7] = 0.0f;
    return v;
}

TEST(HalfPlanes, EveryValueKeepsItsStatedPrecision) {
    const test::TempDir dir;
    for (float largest : {1.0f, 3.7e-9f, 2.5e12f, 65504.0f, 1e-30f}) {
        const std::vector<float> v = spreadValues(5000, largest, 3);
        const std::vector<float> back = throughFile(dir, v);
        ASSERT_EQ(back.size(), v.size());
        for (std::size_t i = 0; i < v.size(); ++i) {
            const float a = std::abs(v[i]);
            const double bound = a >= largest * std::exp2(-28.0f) ? std::exp2(-11.0) * a : std::exp2(-39.0) * largest;
            ASSERT_LE(std::abs(double(back[i]) - double(v[i])), bound) << "largest " << largest << " value " << v[i];
            if (v[i] == 0.0f) {
                EXPECT_EQ(back[i], 0.0f);
            }
        }
    }
}

TEST(HalfPlanes, RoundingGivesWhatTheFileGivesBackAndIsIdempotent) {
    const test::TempDir dir;
    std::vector<float> v = spreadValues(3000, 0.02f, 5);
    const std::vector<float> back = throughFile(dir, v);
    roundToHalfPlanes(v);
    EXPECT_EQ(bits(v), bits(back));
    const std::vector<float> once = v;
    roundToHalfPlanes(v);
    EXPECT_EQ(bits(v), bits(once));
    EXPECT_EQ(bits(throughFile(dir, v)), bits(v));
}

TEST(HalfPlanes, ALargestValueThatRoundsUpToTheNextOctaveKeepsTheScale) {
    // 32767.99 lies in (2^14, 2^15] and rounds up to 2^15 as a half: rounding again must
    // not move to a scale one octave coarser (and lose a bit of the small values).
    // 2^-14 (1 + 2^-10) is a normal half at scale 2^0, but would lose its last bit as a
    // subnormal at scale 2^1.
    const float small = (1.0f + std::exp2(-10.0f)) * std::exp2(-14.0f);
    std::vector<float> v = {32767.99f, small};
    roundToHalfPlanes(v);
    EXPECT_EQ(v[0], 32768.0f);
    EXPECT_EQ(v[1], small);
    const std::vector<float> once = v;
    roundToHalfPlanes(v);
    EXPECT_EQ(bits(v), bits(once));
}

TEST(HalfPlanes, EmptyAndAllZeroArraysRoundTrip) {
    const test::TempDir dir;
    EXPECT_TRUE(throughFile(dir, {}).empty());
    const std::vector<float> zeros(10, 0.0f);
    EXPECT_EQ(throughFile(dir, zeros), zeros);
}

// Writes `bytes` as one raw chunk and decodes `count` varints from it.
std::vector<std::int64_t> varintsFrom(const test::TempDir& dir, const std::vector<std::byte>& bytes,
                                      std::uint64_t count) {
    const auto path = dir / "v.opal";
    writeChunkedFile(path, kCodecKind, std::vector{ChunkProducer{"VINT", ChunkCodec::Raw, true, [&](ChunkSink& s) {
                                                               s.write(bytes);
                                                           }}});
    ChunkedFileReader reader(path, kCodecKind);
    ChunkSource source = reader.open("VINT");
    std::vector<std::int64_t> values = readVarints(source, count, "steps");
    source.finish();
    return values;
}

std::vector<std::byte> varintStream(std::uint64_t declared, std::initializer_list<unsigned> bytes) {
    std::vector<std::byte> out;
    for (int i = 0; i < 8; ++i) out.push_back(std::byte((declared >> (8 * i)) & 0xff));
    for (unsigned b : bytes) out.push_back(std::byte(b));
    return out;
}

TEST(Varints, RoundTripSignedValuesOfEveryLength) {
    const test::TempDir dir;
    std::vector<std::int64_t> values = {0, 1, -1, 63, -64, 64, -65, 8191, -8192, 1 << 20, -(1 << 27)};
    values.push_back(std::numeric_limits<std::int64_t>::max());
    values.push_back(std::numeric_limits<std::int64_t>::min());
    std::mt19937_64 rng(9);
    for (int i = 0; i < 2000; ++i) values.push_back(std::int64_t(rng()) >> (rng() % 64));
    const auto path = dir / "r.opal";
    writeChunkedFile(path, kCodecKind, std::vector{ChunkProducer{"VINT", ChunkCodec::Zstd, true, [&](ChunkSink& s) {
                                                               writeVarints(s, values);
                                                           }}});
    ChunkedFileReader reader(path, kCodecKind);
    ChunkSource source = reader.open("VINT");
    EXPECT_EQ(readVarints(source, values.size(), "values"), values);
    source.finish();
    // Small magnitudes take one byte: 1, -1, 63 and -64 are zigzag 2, 1, 126, 127.
    EXPECT_EQ(varintsFrom(dir, varintStream(4, {2, 1, 126, 127}), 4), (std::vector<std::int64_t>{1, -1, 63, -64}));
}

TEST(Varints, MalformedStreamsAreRejectedNamingWhatAndWhere) {
    const test::TempDir dir;
    EXPECT_NE(errorOf([&] { varintsFrom(dir, varintStream(2, {0x80, 0x80}), 1); }).find("steps: the bytes end inside value 0"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { varintsFrom(dir, varintStream(3, {1, 2, 3}), 2); }).find("steps: 1 bytes left after 2 values"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { varintsFrom(dir, varintStream(1, {1}), 2); }).find("2 values cannot fit in 1 bytes"),
              std::string::npos);
    EXPECT_NE(errorOf([&] { varintsFrom(dir, varintStream(10, {0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0x02}), 1); })
                  .find("steps: value 0 exceeds 64 bits"),
              std::string::npos);
    // A byte count beyond the chunk is refused before anything is allocated for it.
    EXPECT_NE(errorOf([&] { varintsFrom(dir, varintStream(1u << 30, {1}), 1); }).find("steps"), std::string::npos);
}

}  // namespace
}  // namespace opal
