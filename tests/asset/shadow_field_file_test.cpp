// The light sidecar (schema/asset/LIGHTFIELD.md): round trip, and corrupt, truncated or
// inconsistent files refused with the file, the chunk and the problem named.
#include "schema/asset/chunked_file.h"
#include "schema/asset/shadow_field_file.h"
#include "schema/error.h"
#include "synthetic_shadow_field.h"
#include "test_files.h"

#include <gtest/gtest.h>

#include <bit>

namespace opal {
namespace {
using test::expectContains;
using test::errorOf;

using test::TempDir;
using namespace shadow_field_chunk;

using test::bits;

void expectSame(const ShadowField& a, const ShadowField& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.centre, b.centre);
    EXPECT_EQ(a.emitterRadius, b.emitterRadius);
    EXPECT_EQ(a.radii, b.radii);
    EXPECT_EQ(a.directionFaceSize, b.directionFaceSize);
    EXPECT_EQ(a.mapFaceSize, b.mapFaceSize);
    EXPECT_EQ(a.keptEnergy, b.keptEnergy);
    EXPECT_EQ(a.bakeId, b.bakeId);
    EXPECT_EQ(a.offsets, b.offsets);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(bits(a.values), bits(b.values));
    EXPECT_EQ(a.views.directionFaceSize, b.views.directionFaceSize);
    EXPECT_EQ(a.views.imageSize, b.views.imageSize);
    EXPECT_EQ(bits(a.views.radiance), bits(b.views.radiance));
}

// Writes a container of kind SFLD with the given chunks as they are (no field checks), so
// that a test can hand the reader a well-formed file with inconsistent contents.
void writeRawField(const std::filesystem::path& path, const ShadowField& f,
                   const std::function<void(ChunkSink&)>& radii) {
    const ChunkProducer chunks[] = {
        {kHeader, ChunkCodec::Raw, true,
         [&](ChunkSink& s) {
             s.writeString(f.name);
             for (int i = 0; i < 3; ++i) s.writeF64(f.centre[i]);
             s.writeF64(f.emitterRadius);
             s.writeU32(f.shells());
             s.writeU32(f.directionFaceSize);
             s.writeU32(f.mapFaceSize);
             s.writeF64(f.keptEnergy);
         }},
        {kRadii, ChunkCodec::Raw, true, radii},
    };
    writeChunkedFile(path, kShadowFieldKind, chunks);
}

TEST(ShadowFieldFile, RoundTripIsBitExact) {
    TempDir dir;
    const ShadowField original = test::irregularShadowField();
    ASSERT_GT(original.indices.size(), 100u);
    writeShadowFieldFile(dir / "light.opal", original);
    expectSame(original, readShadowFieldFile(dir / "light.opal"));
}

TEST(ShadowFieldFile, TwoWritesAreByteIdentical) {
    TempDir dir;
    const ShadowField field = test::irregularShadowField();
    writeShadowFieldFile(dir / "a.opal", field);
    writeShadowFieldFile(dir / "b.opal", field);
    EXPECT_EQ(test::readBytes(dir / "a.opal"), test::readBytes(dir / "b.opal"));
}

TEST(ShadowFieldFile, ViewsAreOptionalAndChecked) {
    TempDir dir;
    ShadowField f = test::irregularShadowField();
    ASSERT_FALSE(f.views.empty());
    f.views = {};
    writeShadowFieldFile(dir / "plain.opal", f);
    EXPECT_TRUE(readShadowFieldFile(dir / "plain.opal").views.empty());
    ChunkedFileReader plain(dir / "plain.opal", kShadowFieldKind);
    EXPECT_EQ(plain.find(kViews), nullptr);

    f = test::irregularShadowField();
    f.views.radiance[5] = -1.0f;  // radiance is never negative
    expectContains(errorOf([&] { writeShadowFieldFile(dir / "bad.opal", f); }),
                   {"bad.opal", "chunk 'VIEW'", "view radiance -1 at 5"});
    f = test::irregularShadowField();
    f.views.imageSize = 3;
    expectContains(errorOf([&] { writeShadowFieldFile(dir / "bad.opal", f); }),
                   {"bad.opal", "chunk 'VIEW'", "view image face size 3"});
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.opal"));
}

TEST(ShadowFieldFile, AnAssetSidecarIsNotALightSidecar) {
    TempDir dir;
    writeChunkedFile(dir / "asset.opal", FileKind{"SCAT", {2, 2}}, {});
    expectContains(errorOf([&] { readShadowFieldFile(dir / "asset.opal"); }), {"asset.opal", "SCAT", "SFLD"});
}

TEST(ShadowFieldFile, EveryTruncationIsRefusedNamingTheFile) {
    TempDir dir;
    writeShadowFieldFile(dir / "full.opal", test::irregularShadowField());
    const std::vector<std::byte> bytes = test::readBytes(dir / "full.opal");
    for (std::size_t size = 0; size < bytes.size(); size += 1 + size / 7) {
        test::writeBytes(dir / "cut.opal", std::vector<std::byte>(bytes.begin(), bytes.begin() + std::ptrdiff_t(size)));
        expectContains(errorOf([&] { readShadowFieldFile(dir / "cut.opal"); }), {"cut.opal"});
    }
}

TEST(ShadowFieldFile, EveryFlippedByteIsRefusedNamingTheFile) {
    TempDir dir;
    writeShadowFieldFile(dir / "light.opal", test::irregularShadowField());
    const std::vector<std::byte> bytes = test::readBytes(dir / "light.opal");
    test::writeBytes(dir / "bad.opal", bytes);
    for (std::size_t at = 0; at < bytes.size(); at += 1 + at / 13) {
        test::patchByte(dir / "bad.opal", at, bytes[at] ^ std::byte{0x20});
        expectContains(errorOf([&] { readShadowFieldFile(dir / "bad.opal"); }), {"bad.opal"});
        test::patchByte(dir / "bad.opal", at, bytes[at]);
    }
}

TEST(ShadowFieldFile, CorruptMapsNameTheChunk) {
    TempDir dir;
    writeShadowFieldFile(dir / "light.opal", test::irregularShadowField());
    ChunkedFileReader reader(dir / "light.opal", kShadowFieldKind);
    const ChunkInfo* maps = reader.find(kMaps);
    ASSERT_NE(maps, nullptr);
    const std::vector<std::byte> bytes = test::readBytes(dir / "light.opal");
    test::patchByte(dir / "light.opal", maps->offset + maps->storedSize / 2,
                    bytes[maps->offset + maps->storedSize / 2] ^ std::byte{1});
    expectContains(errorOf([&] { readShadowFieldFile(dir / "light.opal"); }),
                   {"light.opal", "chunk 'MAPS'", "checksum mismatch"});
}

TEST(ShadowFieldFile, InconsistentContentsNameChunkAndProblem) {
    TempDir dir;
    const ShadowField f = test::irregularShadowField();
    writeRawField(dir / "descending.opal", f, [&](ChunkSink& s) {
        std::vector<double> radii = f.radii;
        std::swap(radii[0], radii[1]);
        s.writeArray<double>(radii);
    });
    expectContains(errorOf([&] { readShadowFieldFile(dir / "descending.opal"); }),
                   {"descending.opal", "chunk 'RADI'", "shell 1 radius", "is not above shell 0"});
    writeRawField(dir / "short.opal", f, [&](ChunkSink& s) { s.writeArray<double>(std::span(f.radii).first(2)); });
    expectContains(errorOf([&] { readShadowFieldFile(dir / "short.opal"); }), {"short.opal", "chunk 'RADI'"});
    writeRawField(dir / "nomaps.opal", f, [&](ChunkSink& s) { s.writeArray<double>(f.radii); });
    expectContains(errorOf([&] { readShadowFieldFile(dir / "nomaps.opal"); }), {"nomaps.opal", "missing chunk 'MAPS'"});
}

TEST(ShadowFieldFile, WriterRefusesWhatTheReaderWould) {
    TempDir dir;
    ShadowField f = test::irregularShadowField();
    f.indices[1] = f.indices[0];  // not ascending within map 0
    expectContains(errorOf([&] { writeShadowFieldFile(dir / "x.opal", f); }), {"x.opal", "MAPS", "not written"});
    f = test::irregularShadowField();
    f.mapFaceSize = 3;
    expectContains(errorOf([&] { writeShadowFieldFile(dir / "x.opal", f); }), {"HEAD", "power of two"});
    f = test::irregularShadowField();
    f.values[4] = NAN;
    expectContains(errorOf([&] { writeShadowFieldFile(dir / "x.opal", f); }), {"MAPS"});
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace opal
