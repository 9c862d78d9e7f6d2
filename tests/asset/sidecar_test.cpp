// The sidecar: bit-exact round trip, determinism, and rejection of every truncation, every
// byte flip and every inconsistency, each naming the file and (where there is one) chunk.
// Byte offsets inside chunks below come from the layout documented in SIDECAR.md.
#include "schema/asset/sidecar.h"

#include "schema/asset/chunked_file.h"
#include "schema/asset/normal_harmonics.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"
#include "tests/asset/synthetic_asset.h"
#include "tests/asset/test_files.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdlib>
#include <cstring>
#include <functional>

namespace opal {
namespace {
using test::expectContains;
using test::errorOf;

using test::TempDir;

using test::bits;

std::vector<std::uint32_t> bits(std::span<const SurfaceSample> samples) {
    std::vector<float> f;
    for (const SurfaceSample& s : samples)
        f.insert(f.end(), {s.position.x, s.position.y, s.position.z, s.normal.x, s.normal.y, s.normal.z, s.area});
    return bits(f);
}

void expectSameSidecarParts(const TranslucentAsset& a, const TranslucentAsset& b) {
    EXPECT_EQ(a.layout.charts, b.layout.charts);
    EXPECT_EQ(a.layout.log2Size, b.layout.log2Size);
    EXPECT_EQ(bits(a.samples), bits(b.samples));
    EXPECT_EQ(a.vertexWeights.offsets, b.vertexWeights.offsets);
    EXPECT_EQ(a.vertexWeights.samples, b.vertexWeights.samples);
    EXPECT_EQ(bits(a.vertexWeights.weights), bits(b.vertexWeights.weights));
    EXPECT_EQ(a.transfer.keepFraction, b.transfer.keepFraction);
    EXPECT_EQ(a.transfer.energyFraction, b.transfer.energyFraction);
    ASSERT_EQ(a.transfer.perBasis.size(), b.transfer.perBasis.size());
    for (std::size_t k = 0; k < a.transfer.perBasis.size(); ++k) EXPECT_EQ(a.transfer.valueStep(k), b.transfer.valueStep(k));
    for (std::size_t k = 0; k < a.transfer.perBasis.size(); ++k) {
        const SparseMatrix &x = a.transfer.perBasis[k], &y = b.transfer.perBasis[k];
        EXPECT_EQ(x.rows, y.rows);
        EXPECT_EQ(x.cols, y.cols);
        EXPECT_EQ(x.rowOffsets, y.rowOffsets);
        EXPECT_EQ(x.columns, y.columns);
        EXPECT_EQ(bits(x.values), bits(y.values));
    }
    EXPECT_EQ(bits(a.transfer.harmonics), bits(b.transfer.harmonics));
    if (!a.transfer.harmonics.empty()) {
        EXPECT_EQ(a.transfer.harmonicSet.count, b.transfer.harmonicSet.count);
        EXPECT_EQ(a.transfer.harmonicSet.centre, b.transfer.harmonicSet.centre);
        EXPECT_EQ(a.transfer.harmonicSet.inverseScale, b.transfer.harmonicSet.inverseScale);
    }
    EXPECT_EQ(a.environment.cubeFaceSize, b.environment.cubeFaceSize);
    EXPECT_EQ(a.environment.fresnelTerms, b.environment.fresnelTerms);
    EXPECT_EQ(a.environment.offsets, b.environment.offsets);
    EXPECT_EQ(a.environment.indices, b.environment.indices);
    EXPECT_EQ(bits(a.environment.values), bits(b.environment.values));
}

// A sidecar's chunks with their raw bytes, to be edited and written back through the
// container API with valid checksums: content errors only the sidecar rules can catch.
struct RawChunk {
    ChunkInfo info;
    std::vector<std::byte> bytes;
};

std::vector<RawChunk> rawChunks(const std::filesystem::path& path) {
    ChunkedFileReader reader(path, kSidecarKind);
    std::vector<RawChunk> chunks;
    for (const ChunkInfo& info : reader.chunks()) {
        ChunkSource source = reader.open(info.tag);
        std::vector<std::byte> bytes(source.remaining());
        source.read(bytes);
        source.finish();
        chunks.push_back({info, std::move(bytes)});
    }
    return chunks;
}

void writeRawChunks(const std::filesystem::path& path, const std::vector<RawChunk>& chunks) {
    std::vector<ChunkProducer> producers;
    for (const RawChunk& c : chunks)
        producers.push_back({c.info.tag, c.info.codec, c.info.required, [&c](ChunkSink& s) { s.write(c.bytes); }});
    writeChunkedFile(path, kSidecarKind, producers);
}

RawChunk& chunk(std::vector<RawChunk>& chunks, ChunkTag tag) {
    for (RawChunk& c : chunks)
        if (c.info.tag == tag) return c;
    throw std::logic_error("no chunk " + tag.str());
}

void putBytes(std::vector<std::byte>& b, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) b[at + i] = std::byte((v >> (8 * i)) & 0xFF);
}

void putF64(std::vector<std::byte>& b, std::size_t at, double v) {
    const auto u = std::bit_cast<std::uint64_t>(v);
    for (int i = 0; i < 8; ++i) b[at + i] = std::byte((u >> (8 * i)) & 0xFF);
}

// Float f as value `index` of a byte-plane array of `count` floats starting at `at`.
void putPlaneFloat(std::vector<std::byte>& b, std::size_t at, std::size_t count, std::size_t index, float f) {
    auto u = std::bit_cast<std::uint32_t>(f);
    for (std::size_t k = 0; k < 4; ++k) b[at + k * count + index] = std::byte((u >> (8 * k)) & 0xFF);
}

TEST(Sidecar, RoundTripIsBitExact) {
    TempDir dir;
    TranslucentAsset original = test::syntheticAsset();
    roundToStoredPrecision(original);  // transfer and environment values are stored as halves
    writeSidecar(dir / "cube.opal", original);
    TranslucentAsset loaded;
    SidecarHeader header = readSidecar(dir / "cube.opal", loaded);
    expectSameSidecarParts(original, loaded);
    EXPECT_EQ(header.name, "syntheticCube");
    EXPECT_EQ(header.unitsPerMm, 0.1);
    EXPECT_EQ(header.sampleCount, 32u);
    EXPECT_EQ(header.basisCount, 3u);
    EXPECT_EQ(header.vertexCount, 12u);
    EXPECT_EQ(header.meshTopologyHash, meshTopologyHash(original.mesh));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"cube.opal"});
}

TEST(Sidecar, TransferAndEnvironmentValuesComeBackAsRoundToStoredPrecisionSays) {
    TempDir dir;
    const TranslucentAsset original = test::syntheticAsset();
    writeSidecar(dir / "cube.opal", original);
    TranslucentAsset loaded;
    readSidecar(dir / "cube.opal", loaded);
    TranslucentAsset rounded = original;
    roundToStoredPrecision(rounded);
    expectSameSidecarParts(rounded, loaded);
    // and rounding changed them where the format rounds: matrices with a value step (the
    // synthetic asset's matrix 0 has none) and the environment's half floats
    EXPECT_EQ(bits(original.transfer.perBasis[0].values), bits(rounded.transfer.perBasis[0].values));
    EXPECT_NE(bits(original.transfer.perBasis[1].values), bits(rounded.transfer.perBasis[1].values));
    EXPECT_NE(bits(original.environment.values), bits(rounded.environment.values));
}

TEST(Sidecar, EnvironmentMayBeAbsent) {
    TempDir dir;
    TranslucentAsset original = test::syntheticAsset(2);
    original.environment.offsets.clear();
    original.environment.indices.clear();
    original.environment.values.clear();
    roundToStoredPrecision(original);
    writeSidecar(dir / "noenv.opal", original);
    TranslucentAsset loaded;
    readSidecar(dir / "noenv.opal", loaded);
    expectSameSidecarParts(original, loaded);
}

// The environment vectors' Fresnel basis (schema/scatter/fresnel_moments.h) travels in the
// optional chunk FBAS; a sidecar without it (every one written before 2.2) is Legendre.
TEST(Sidecar, FresnelBasisRoundTripsAndDefaultsToLegendre) {
    TempDir dir;
    TranslucentAsset original = test::syntheticAsset();
    roundToStoredPrecision(original);
    original.environment.fresnelBasis = FresnelBasis::Schlick;
    writeSidecar(dir / "schlick.opal", original);
    TranslucentAsset loaded;
    readSidecar(dir / "schlick.opal", loaded);
    EXPECT_EQ(loaded.environment.fresnelBasis, FresnelBasis::Schlick);
    EXPECT_TRUE(ChunkedFileReader(dir / "schlick.opal", kSidecarKind).find(sidecar_chunk::kFresnelBasis));

    original.environment.fresnelBasis = FresnelBasis::Legendre;
    writeSidecar(dir / "legendre.opal", original);
    TranslucentAsset legendre;
    legendre.environment.fresnelBasis = FresnelBasis::Schlick;  // overwritten by the read
    readSidecar(dir / "legendre.opal", legendre);
    EXPECT_EQ(legendre.environment.fresnelBasis, FresnelBasis::Legendre);
    EXPECT_FALSE(ChunkedFileReader(dir / "legendre.opal", kSidecarKind).find(sidecar_chunk::kFresnelBasis));

    original.environment.fresnelBasis = FresnelBasis(7);
    writeSidecar(dir / "unknown.opal", original);
    expectContains(errorOf([&] { readSidecar(dir / "unknown.opal", loaded); }),
                   {"unknown.opal", "FBAS", "unknown Fresnel basis 7"});
}

// A choice that travels in its own chunk, flagged required when it is not the default (a
// reader that skipped it would misread the rest); a sidecar without the chunk (every one
// written before it existed) holds the default. field: the choice inside an asset.
template <typename Choice>
void expectRequiredChoiceChunk(Choice& (*field)(TranslucentAsset&), ChunkTag tag, Choice fallback, Choice other,
                               const std::string& unknownMessage) {
    TempDir dir;
    TranslucentAsset original = test::syntheticAsset();
    roundToStoredPrecision(original);
    field(original) = other;
    writeSidecar(dir / "other.opal", original);
    TranslucentAsset loaded;
    readSidecar(dir / "other.opal", loaded);
    EXPECT_EQ(field(loaded), other);
    const ChunkedFileReader file(dir / "other.opal", kSidecarKind);
    ASSERT_TRUE(file.find(tag));
    EXPECT_TRUE(file.find(tag)->required);

    field(original) = fallback;
    writeSidecar(dir / "fallback.opal", original);
    TranslucentAsset old;
    field(old) = other;  // overwritten by the read
    readSidecar(dir / "fallback.opal", old);
    EXPECT_EQ(field(old), fallback);
    EXPECT_FALSE(ChunkedFileReader(dir / "fallback.opal", kSidecarKind).find(tag));

    field(original) = Choice(5);
    writeSidecar(dir / "unknown.opal", original);
    expectContains(errorOf([&] { readSidecar(dir / "unknown.opal", loaded); }),
                   {"unknown.opal", tag.str(), unknownMessage + " 5"});
}

// Where the transfer's self term lives (chunk SELF, 2.3): in the transfer by default.
TEST(Sidecar, SelfTermPlacementRoundTripsAndDefaultsToInTheTransfer) {
    expectRequiredChoiceChunk<SelfTerm>([](TranslucentAsset& a) -> SelfTerm& { return a.transfer.selfTerm; },
                                        sidecar_chunk::kSelfTerm, SelfTerm::InTransfer, SelfTerm::AtRunTime,
                                        "unknown self-term placement");
}

// What the environment vectors hold (chunk ENVK, 2.4): the visible transport by default.
TEST(Sidecar, EnvironmentVectorKindRoundTripsAndDefaultsToVisible) {
    expectRequiredChoiceChunk<EnvironmentVectorKind>(
        [](TranslucentAsset& a) -> EnvironmentVectorKind& { return a.environment.kind; },
        sidecar_chunk::kEnvironmentKind, EnvironmentVectorKind::Visible, EnvironmentVectorKind::Occluded,
        "unknown environment vector kind");
}

// The exact harmonic transfer: chunk HARM (2.5) for the nine normal harmonics, HARP (2.6)
// for the 36 functions with their frame. Both optional, so that an older reader renders
// from the matrices alone; absent means none.
TEST(Sidecar, HarmonicTransferRoundTripsAndIsOptional) {
    TempDir dir;
    TranslucentAsset original = test::syntheticAsset();
    roundToStoredPrecision(original);
    for (const std::uint32_t Q : {9u, 36u}) {
        SCOPED_TRACE(Q);
        const ChunkTag tag = Q == 9 ? sidecar_chunk::kHarmonics : sidecar_chunk::kPositionHarmonics;
        const char* name = Q == 9 ? "HARM" : "HARP";
        original.transfer.harmonicSet = {Q, Imath::V3f(0.25f, -1.5f, 3.0f), 0.125f};
        const std::size_t values = original.samples.size() * original.transfer.perBasis.size() * Q;
        original.transfer.harmonics.clear();
        for (std::size_t i = 0; i < values; ++i) original.transfer.harmonics.push_back(std::sin(float(i)) * 1e-3f);
        writeSidecar(dir / "harm.opal", original);
        const ChunkedFileReader file(dir / "harm.opal", kSidecarKind);
        ASSERT_TRUE(file.find(tag));
        EXPECT_FALSE(file.find(tag)->required);
        EXPECT_FALSE(file.find(Q == 9 ? sidecar_chunk::kPositionHarmonics : sidecar_chunk::kHarmonics));
        TranslucentAsset loaded;
        readSidecar(dir / "harm.opal", loaded);
        if (Q == 9) original.transfer.harmonicSet = {9};  // HARM has no frame
        expectSameSidecarParts(original, loaded);

        const std::vector<float> kept = original.transfer.harmonics;
        original.transfer.harmonics.clear();
        writeSidecar(dir / "none.opal", original);
        EXPECT_FALSE(ChunkedFileReader(dir / "none.opal", kSidecarKind).find(tag));
        readSidecar(dir / "none.opal", loaded);
        EXPECT_TRUE(loaded.transfer.harmonics.empty());

        original.transfer.harmonics.assign(values - 1, 0.0f);
        expectContains(errorOf([&] { writeSidecar(dir / "short.opal", original); }),
                       {"short.opal", name, "expected samples x K x " + std::to_string(Q) + " = " + std::to_string(values)});
        original.transfer.harmonics.assign(values, 0.0f);
        original.transfer.harmonics[7] = std::nanf("");
        expectContains(errorOf([&] { writeSidecar(dir / "nan.opal", original); }),
                       {"nan.opal", name, "harmonic transfer values[7] = nan is not finite"});
        EXPECT_FALSE(std::filesystem::exists(dir / "nan.opal"));

        // A damaged chunk is refused on reading, naming it: the count's K disagrees with HEAD.
        original.transfer.harmonics = kept;
        writeSidecar(dir / "bad.opal", original);
        std::vector<RawChunk> chunks = rawChunks(dir / "bad.opal");
        putBytes(chunk(chunks, tag).bytes, 4, 4);
        writeRawChunks(dir / "bad.opal", chunks);
        const std::string q = std::to_string(Q);
        expectContains(errorOf([&] { readSidecar(dir / "bad.opal", loaded); }),
                       {"bad.opal", name, "32 samples x K = 4 x " + q + " harmonics, expected 32 x 3 x " + q});
    }
    // The 36 need a usable frame.
    original.transfer.harmonicSet.inverseScale = 0.0f;
    expectContains(errorOf([&] { writeSidecar(dir / "frame.opal", original); }),
                   {"frame.opal", "HARP", "frame (centre and inverse scale) is not finite with a positive scale"});
    original.transfer.harmonicSet = {12};
    expectContains(errorOf([&] { writeSidecar(dir / "count.opal", original); }),
                   {"count.opal", "a harmonic set of 12 functions, expected 9 or 36"});
}

// A file holding both harmonic transfers is refused, naming the two chunks.
TEST(Sidecar, BothHarmonicTransfersAreRefused) {
    TempDir dir;
    TranslucentAsset a = test::syntheticAsset();
    a.transfer.harmonicSet = {9};
    a.transfer.harmonics.assign(a.samples.size() * a.transfer.perBasis.size() * 9, 0.25f);
    writeSidecar(dir / "nine.opal", a);
    a.transfer.harmonicSet = {36};
    a.transfer.harmonics.assign(a.samples.size() * a.transfer.perBasis.size() * 36, 0.25f);
    writeSidecar(dir / "both.opal", a);
    std::vector<RawChunk> chunks = rawChunks(dir / "both.opal");
    std::vector<RawChunk> nine = rawChunks(dir / "nine.opal");
    chunks.push_back(chunk(nine, sidecar_chunk::kHarmonics));
    writeRawChunks(dir / "both.opal", chunks);
    TranslucentAsset loaded;
    expectContains(errorOf([&] { readSidecar(dir / "both.opal", loaded); }), {"both.opal", "'HARM' and 'HARP'"});
}

TEST(Sidecar, TwoWritesAreByteIdentical) {
    TempDir dir;
    TranslucentAsset a = test::syntheticAsset();
    writeSidecar(dir / "a.opal", a);
    writeSidecar(dir / "b.opal", a);
    EXPECT_EQ(test::readBytes(dir / "a.opal"), test::readBytes(dir / "b.opal"));
}

// Shortening the file one byte at a time visits every proper prefix of it.
TEST(Sidecar, EveryTruncationIsRejected) {
    TempDir dir;
    auto path = dir / "cut.opal";
    writeSidecar(path, test::syntheticAsset());
    const std::size_t size = std::filesystem::file_size(path);
    int failures = 0;
    for (std::size_t length = size; length-- > 0;) {
        std::filesystem::resize_file(path, length);
        TranslucentAsset asset;
        std::string message = errorOf([&] { readSidecar(path, asset); });
        if (message.find("cut.opal") == std::string::npos || message.find("NOT AN") != std::string::npos) {
            if (++failures < 5) ADD_FAILURE() << "length " << length << ": " << message;
        }
        if (!asset.samples.empty()) ADD_FAILURE() << "length " << length << ": asset modified";
    }
    EXPECT_EQ(failures, 0);
}

TEST(Sidecar, EveryByteFlipIsRejectedNamingTheChunk) {
    TempDir dir;
    auto path = dir / "flip.opal";
    writeSidecar(path, test::syntheticAsset());
    const std::vector<std::byte> whole = test::readBytes(path);
    ASSERT_LT(whole.size(), 16000u);  // keeps the loop fast
    ChunkedFileReader pristine(path, kSidecarKind);
    std::vector<ChunkInfo> chunks(pristine.chunks().begin(), pristine.chunks().end());
    int failures = 0;
    for (std::size_t at = 0; at < whole.size(); ++at) {
        test::patchByte(path, at, whole[at] ^ std::byte{0xFF});
        TranslucentAsset asset;
        std::string message = errorOf([&] { readSidecar(path, asset); });
        test::patchByte(path, at, whole[at]);
        std::string expected = "flip.opal";
        for (const ChunkInfo& c : chunks)
            if (at >= c.offset && at < c.offset + c.storedSize) expected = "flip.opal: chunk '" + c.tag.str() + "'";
        if (message.find(expected) == std::string::npos || message.find("NOT AN") != std::string::npos) {
            if (++failures < 5) ADD_FAILURE() << "byte " << at << ": " << message << "\n  expected: " << expected;
        }
    }
    EXPECT_EQ(failures, 0);
    EXPECT_EQ(test::readBytes(path), whole);
}

TEST(Sidecar, OtherMajorVersionsAreRejectedNewerMinorAccepted) {
    TempDir dir;
    auto path = dir / "v.opal";
    writeSidecar(path, test::syntheticAsset());
    std::vector<std::byte> file = test::readBytes(path);
    test::putU16(file, 14, 7);  // minor 1.7
    test::resealHeader(file);
    test::writeBytes(path, file);
    TranslucentAsset asset;
    readSidecar(path, asset);
    test::putU16(file, 12, 3);  // major 3.7
    test::resealHeader(file);
    test::writeBytes(path, file);
    expectContains(errorOf([&] { readSidecar(path, asset); }), {"v.opal", "version 3.7 is newer", "update Opal"});
    test::putU16(file, 12, 1);  // major 1.7: float planes, older than this reader
    test::resealHeader(file);
    test::writeBytes(path, file);
    expectContains(errorOf([&] { readSidecar(path, asset); }), {"v.opal", "version 1.7 is older", "write the file again"});
}

struct ContentCase {
    ChunkTag tag;  // edited; the error names this chunk unless `reported` is set

    std::function<void(std::vector<std::byte>&, const TranslucentAsset&)> edit;
    std::string problem;
    ChunkTag reported{};
};

TEST(Sidecar, ContentInconsistenciesAreRejectedNamingTheChunk) {
    const std::size_t n = 32;  // samples
    const std::vector<ContentCase> cases = {
        {"CHRT", [](auto& b, auto&) { putBytes(b, 0, 3); }, "layout has 48 cells, the header says 32 samples"},
        {"HEAD", [](auto& b, auto&) { putBytes(b, 4 + 13 + 8 + 8, 4); }, "K = 3 matrices, the header says 4", "TRNS"},
        {"SMPL", [&](auto& b, auto&) { putPlaneFloat(b, 8 + 12 * n, 3 * n, 0, 2.0f); }, "sample 0: normal has length 2"},
        {"SMPL", [&](auto& b, auto&) { putPlaneFloat(b, 8 + 24 * n, n, 5, 0.0f); }, "sample 5: area 0 is not positive"},
        {"VWGT", [](auto& b, auto&) { putBytes(b, 4 + 8 + 13 * 4, 32); }, "vertex samples row 0: index 32 >= 32"},
        {"VWGT", [](auto& b, auto&) { putBytes(b, 4 + 8 + 4, 0xFFFF); }, "vertex offsets decrease at row 1"},
        {"TRNS", [&](auto& b, auto&) { putBytes(b, 20 + 16 + (n + 1) * 8, 32); }, ": index 32 >= 32"},
        {"TRNS",
         [&](auto& b, const TranslucentAsset& a) {  // matrix 0 is stored exactly (step 0)
             const std::size_t nnz = a.transfer.perBasis[0].values.size();
             putPlaneFloat(b, 20 + 16 + (n + 1) * 8 + nnz * 4 + 8, nnz, 0, std::nanf(""));
         },
         "matrix 0 values[0] = nan is not finite"},
        {"TRNS",
         [&](auto& b, const TranslucentAsset& a) {
             const std::size_t nnz = a.transfer.perBasis[0].values.size();
             putF64(b, 20 + 16 + (n + 1) * 8 + nnz * 4, -0.5);
         },
         "matrix 0: value step -0.5 is not a finite number >= 0"},
        {"ENVT",
         [&](auto& b, const TranslucentAsset& a) {  // half NaN 0x7e00 as value 0's two planes
             const std::size_t nnz = a.environment.values.size(), at = 24 + (2 * n + 1) * 4 + nnz * 4 + 4;
             b[at] = std::byte{0x00};
             b[at + nnz] = std::byte{0x7e};
         },
         "values: value 0 is not finite"},
        {"ENVT",
         [&](auto& b, const TranslucentAsset& a) {
             putBytes(b, 24 + (2 * n + 1) * 4 + a.environment.values.size() * 4, 112);
         },
         "values: half-float scale exponent 112 is outside [-160, 111]"},
        {"ENVT",  // the largest scale the half planes allow: finite values the runtime would overflow on
         [&](auto& b, const TranslucentAsset& a) {
             putBytes(b, 24 + (2 * n + 1) * 4 + a.environment.values.size() * 4, 111);
         },
         "a transport value's magnitude is at most 4 pi"},
        // What the runtime cannot render is refused by the reader, not at the first light.
        {"ENVT", [](auto& b, auto&) { putBytes(b, 0, 2048); }, "cube face size 2048 is not a power of two in [1, 1024]"},
        {"ENVT", [](auto& b, auto&) { putBytes(b, 4, 4); }, "4 Fresnel terms, outside [1, 3]"},
        {"TRNS", [&](auto& b, auto&) { putBytes(b, 24, 31); }, "matrix 0: 32 x 31, expected 32 x 32"},
        {"ENVT", [&](auto& b, auto&) { putBytes(b, 24 + (2 * n + 1) * 4, 24); }, ": index 24 >= 24"},
        {"ENVT", [](auto& b, auto&) { putBytes(b, 0, 3); }, "cube face size 3 is not a power of two"},
    };
    TempDir dir;
    TranslucentAsset original = test::syntheticAsset();
    writeSidecar(dir / "good.opal", original);
    for (const ContentCase& c : cases) {
        std::vector<RawChunk> chunks = rawChunks(dir / "good.opal");
        c.edit(chunk(chunks, c.tag).bytes, original);
        writeRawChunks(dir / "bad.opal", chunks);
        TranslucentAsset asset;
        expectContains(errorOf([&] { readSidecar(dir / "bad.opal", asset); }),
                       {"bad.opal: chunk '" + (c.reported == ChunkTag{} ? c.tag : c.reported).str() + "'", c.problem});
    }
}

// The file's bytes with chunk `tag`'s table entry claiming `rawSize` decoded bytes, every
// checksum of the header and table recomputed: a file only the size checks can refuse.
std::vector<std::byte> withClaimedRawSize(std::vector<std::byte> file, ChunkTag tag, std::uint64_t rawSize) {
    const auto get64 = [&](std::size_t at) {
        std::uint64_t v = 0;
        for (int i = 7; i >= 0; --i) v = (v << 8) | std::uint64_t(file[at + std::size_t(i)]);
        return v;
    };
    const auto put64 = [&](std::size_t at, std::uint64_t v) {
        for (int i = 0; i < 8; ++i) file[at + std::size_t(i)] = std::byte((v >> (8 * i)) & 0xFF);
    };
    const std::size_t tableOffset = std::size_t(get64(24)), tableBytes = file.size() - tableOffset;
    for (std::size_t entry = tableOffset; entry < file.size(); entry += 48)
        if (std::memcmp(&file[entry], tag.chars.data(), 4) == 0) put64(entry + 24, rawSize);
    put64(40, xxh64(std::span(file).subspan(tableOffset, tableBytes)));
    put64(56, xxh64(std::span(file).first(56)));
    return file;
}

// Sets an environment variable for one scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) { setenv(name, value.c_str(), 1); }
    ~ScopedEnv() { unsetenv(name_); }

private:
    const char* name_;
};

TEST(Sidecar, DeclaredDecodedSizesAreCappedBeforeAnyAllocation) {
    TempDir dir;
    writeSidecar(dir / "good.opal", test::syntheticAsset());
    const std::vector<std::byte> good = test::readBytes(dir / "good.opal");
    std::uint64_t decoded = 0, storedTransfer = 0;
    {
        ChunkedFileReader reader(dir / "good.opal", kSidecarKind);
        for (const ChunkInfo& c : reader.chunks()) decoded += c.rawSize;
        storedTransfer = reader.find("TRNS")->storedSize;
    }
    TranslucentAsset asset;
    {  // the cap counts every chunk together
        ScopedEnv cap("OPAL_SIDECAR_MAX_BYTES", std::to_string(decoded - 1));
        expectContains(errorOf([&] { readSidecar(dir / "good.opal", asset); }),
                       {"good.opal: chunk table: the chunks decode to " + std::to_string(decoded) + " bytes",
                        "more than the " + std::to_string(decoded - 1), "OPAL_SIDECAR_MAX_BYTES"});
    }
    {
        ScopedEnv cap("OPAL_SIDECAR_MAX_BYTES", std::to_string(decoded));
        readSidecar(dir / "good.opal", asset);  // at the cap: read
    }
    {
        ScopedEnv cap("OPAL_SIDECAR_MAX_BYTES", "lots");
        expectContains(errorOf([&] { readSidecar(dir / "good.opal", asset); }), {"OPAL_SIDECAR_MAX_BYTES", "'lots'"});
    }
    // A transfer chunk claiming the most its stored bytes could expand to through zstd: a
    // file of kilobytes asking for megabytes (gigabytes, for a megabyte file). Refused at the
    // table, before any chunk is decoded, when that exceeds the cap...
    const std::uint64_t claimed = storedTransfer * container::kMaxZstdExpansion;
    test::writeBytes(dir / "claims.opal", withClaimedRawSize(good, "TRNS", claimed));
    {
        ScopedEnv cap("OPAL_SIDECAR_MAX_BYTES", std::to_string(claimed / 2));
        expectContains(errorOf([&] { readSidecar(dir / "claims.opal", asset); }),
                       {"claims.opal: chunk table: the chunks decode to", "more than the"});
    }
    // ...and, under the default cap, by the chunk's own decoder when the data ends early.
    expectContains(errorOf([&] { readSidecar(dir / "claims.opal", asset); }), {"claims.opal: chunk 'TRNS'"});
    // One byte more than zstd can expand the stored bytes to is refused outright.
    test::writeBytes(dir / "more.opal", withClaimedRawSize(good, "TRNS", claimed + 1));
    expectContains(errorOf([&] { readSidecar(dir / "more.opal", asset); }),
                   {"more.opal: chunk 'TRNS'", "more than zstd can expand"});
}

TEST(Sidecar, MissingAndUnknownRequiredChunksAreRejected) {
    TempDir dir;
    writeSidecar(dir / "good.opal", test::syntheticAsset());
    std::vector<RawChunk> chunks = rawChunks(dir / "good.opal");
    TranslucentAsset asset;

    std::vector<RawChunk> withoutEnv(chunks.begin(), chunks.end() - 1);
    writeRawChunks(dir / "bad.opal", withoutEnv);
    expectContains(errorOf([&] { readSidecar(dir / "bad.opal", asset); }), {"bad.opal", "missing chunk 'ENVT'"});

    std::vector<RawChunk> withOptional = chunks;
    withOptional.push_back({{"XTRA", ChunkCodec::Raw, false}, {std::byte{1}}});
    writeRawChunks(dir / "bad.opal", withOptional);
    readSidecar(dir / "bad.opal", asset);  // unknown optional chunks are skipped

    withOptional.back().info.required = true;
    writeRawChunks(dir / "bad.opal", withOptional);
    expectContains(errorOf([&] { readSidecar(dir / "bad.opal", asset); }), {"bad.opal: chunk 'XTRA'", "required"});
}

TEST(Sidecar, WriterRefusesInconsistentAssetsAndKeepsThePreviousFile) {
    TempDir dir;
    auto path = dir / "keep.opal";
    writeSidecar(path, test::syntheticAsset());
    const std::vector<std::byte> before = test::readBytes(path);

    TranslucentAsset bad = test::syntheticAsset();
    bad.transfer.perBasis[1].columns.back() = 32;
    expectContains(errorOf([&] { writeSidecar(path, bad); }), {"keep.opal: chunk 'TRNS'", "matrix 1 columns", ">= 32"});
    bad = test::syntheticAsset();
    bad.samples.pop_back();
    expectContains(errorOf([&] { writeSidecar(path, bad); }), {"keep.opal: chunk 'SMPL'", "31 samples"});
    bad = test::syntheticAsset();
    bad.vertexWeights.weights[0] += 0.5f;
    expectContains(errorOf([&] { writeSidecar(path, bad); }), {"keep.opal: chunk 'VWGT'", "vertex 0: weights sum"});
    bad = test::syntheticAsset();
    bad.environment.offsets.pop_back();
    expectContains(errorOf([&] { writeSidecar(path, bad); }), {"keep.opal: chunk 'ENVT'", "offsets for 64 rows"});

    EXPECT_EQ(test::readBytes(path), before);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"keep.opal"});
}

TEST(Sidecar, HeaderIsCheckedAgainstTheLayer) {
    TempDir dir;
    TranslucentAsset a = test::syntheticAsset();
    const std::size_t L = 2;
    a.basis = ProfileBasis({0.0, 1.0}, {0.5, 0.5}, std::vector<double>(3 * L, 0.1), {3.0, 2.0, 1.0},
                           EditableRange::coveringPresets());
    writeSidecar(dir / "m.opal", a);
    TranslucentAsset layer = a;
    SidecarHeader header = readSidecar(dir / "m.opal", layer);
    checkSidecarMatches(header, a, dir / "m.opal");

    TranslucentAsset other = a;
    other.name = "otherAsset";
    expectContains(errorOf([&] { checkSidecarMatches(header, other, dir / "m.opal"); }),
                   {"m.opal: chunk 'HEAD'", "'otherAsset'"});
    other = a;
    other.mesh.faceVertexIndices[0] = 5;
    expectContains(errorOf([&] { checkSidecarMatches(header, other, dir / "m.opal"); }), {"faces differ"});
    other = a;
    other.mesh.points.pop_back();
    expectContains(errorOf([&] { checkSidecarMatches(header, other, dir / "m.opal"); }), {"12 vertices"});
    other = a;
    other.basis = ProfileBasis();
    expectContains(errorOf([&] { checkSidecarMatches(header, other, dir / "m.opal"); }), {"K = 3", "0 functions"});
}

}  // namespace
}  // namespace opal
