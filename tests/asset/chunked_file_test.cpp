// The generic container: round trips, atomic replacement, and rejection of damaged,
// foreign, newer or inconsistent files with messages naming the file and chunk.
#include "schema/asset/chunked_file.h"

#include "schema/error.h"
#include "tests/asset/test_files.h"

#include <gtest/gtest.h>

#include <random>

namespace opal {
namespace {

using test::TempDir;

const FileKind kChunkedKind{"TEST", {1, 2}};

std::vector<std::byte> pattern(std::size_t n, std::uint32_t seed, bool compressible) {
    std::mt19937 rng(seed);
    std::vector<std::byte> b(n);
    for (std::size_t i = 0; i < n; ++i) b[i] = std::byte(compressible ? (i / 64) & 0xFF : rng() & 0xFF);
    return b;
}

ChunkProducer bytesChunk(ChunkTag tag, ChunkCodec codec, const std::vector<std::byte>& bytes, bool required = true) {
    return {tag, codec, required, [&bytes](ChunkSink& s) { s.write(bytes); }};
}

std::vector<std::byte> readChunk(ChunkedFileReader& reader, ChunkTag tag) {
    ChunkSource source = reader.open(tag);
    std::vector<std::byte> bytes(source.remaining());
    source.read(bytes);
    source.finish();
    return bytes;
}

// Expects `f` to throw opal::Error whose message contains every one of `parts`.
template <class F>
void expectError(F&& f, std::initializer_list<std::string> parts) {
    try {
        f();
        ADD_FAILURE() << "no error thrown";
    } catch (const Error& e) {
        for (const std::string& p : parts) EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
    }
}

TEST(ChunkedFile, RoundTripsRawZstdEmptyAndLargeChunks) {
    TempDir dir;
    auto path = dir / "c.opal";
    auto small = pattern(100, 1, false), large = pattern(3 << 20, 2, true), empty = std::vector<std::byte>{};
    std::vector<ChunkProducer> chunks = {bytesChunk("RAW1", ChunkCodec::Raw, small),
                                         bytesChunk("ZST1", ChunkCodec::Zstd, large),
                                         bytesChunk("EMPZ", ChunkCodec::Zstd, empty),
                                         bytesChunk("EMPR", ChunkCodec::Raw, empty)};
    writeChunkedFile(path, kChunkedKind, chunks);

    ChunkedFileReader reader(path, kChunkedKind);
    EXPECT_EQ(reader.version().major, 1);
    EXPECT_EQ(reader.version().minor, 2);
    ASSERT_EQ(reader.chunks().size(), 4u);
    EXPECT_EQ(readChunk(reader, "RAW1"), small);
    EXPECT_EQ(readChunk(reader, "ZST1"), large);
    EXPECT_EQ(readChunk(reader, "EMPZ"), empty);
    EXPECT_EQ(readChunk(reader, "EMPR"), empty);
    // The table against the bytes on disk: checksums are XXH64 of exactly those bytes.
    std::vector<std::byte> file = test::readBytes(path);
    for (const ChunkInfo& c : reader.chunks()) {
        EXPECT_EQ(c.storedChecksum, xxh64(std::span(file).subspan(c.offset, c.storedSize))) << c.tag.str();
        EXPECT_TRUE(c.required);
    }
    EXPECT_EQ(reader.find("ZST1")->rawSize, large.size());
    EXPECT_LT(reader.find("ZST1")->storedSize, large.size() / 20);  // compressible pattern
    EXPECT_EQ(reader.find("RAW1")->storedSize, small.size());
}

TEST(ChunkedFile, WritesAreDeterministic) {
    TempDir dir;
    auto data = pattern(200000, 3, false);
    std::vector<ChunkProducer> chunks = {bytesChunk("DATA", ChunkCodec::Zstd, data)};
    writeChunkedFile(dir / "a.opal", kChunkedKind, chunks);
    writeChunkedFile(dir / "b.opal", kChunkedKind, chunks);
    EXPECT_EQ(test::readBytes(dir / "a.opal"), test::readBytes(dir / "b.opal"));
}

TEST(ChunkedFile, WriterFailingMidWriteLeavesPreviousFileAndNoTemporary) {
    TempDir dir;
    auto path = dir / "asset.opal";
    auto data = pattern(2 << 20, 4, false);  // larger than the writer's buffer: bytes hit the disk
    writeChunkedFile(path, kChunkedKind, std::vector{bytesChunk("OLD1", ChunkCodec::Zstd, data)});
    const std::vector<std::byte> before = test::readBytes(path);

    std::vector<ChunkProducer> failing = {
        bytesChunk("NEW1", ChunkCodec::Zstd, data),
        {"NEW2", ChunkCodec::Zstd, true, [&](ChunkSink& s) {
             s.write(data);
             throw Error("producer failed after writing part of chunk NEW2");
         }},
    };
    expectError([&] { writeChunkedFile(path, kChunkedKind, failing); }, {"producer failed"});
    EXPECT_EQ(test::readBytes(path), before);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"asset.opal"});

    expectError([&] { writeChunkedFile(dir / "fresh.opal", kChunkedKind, failing); }, {"producer failed"});
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"asset.opal"});
}

TEST(ChunkedFile, WriterRejectsBadChunkListsAndPaths) {
    TempDir dir;
    std::vector<std::byte> none;
    expectError([&] { writeChunkedFile(dir / "d.opal", kChunkedKind, std::vector{bytesChunk("SAME", ChunkCodec::Raw, none),
                                                                        bytesChunk("SAME", ChunkCodec::Raw, none)}); },
                {"d.opal", "chunk 'SAME'", "twice"});
    expectError([&] { writeChunkedFile(dir / "missing" / "x.opal", kChunkedKind, {}); }, {"x.opal", "temporary"});
    expectError([&] { writeChunkedFile(dir / "l.opal", kChunkedKind, std::vector{bytesChunk("ZZZZ", ChunkCodec::Zstd, none)}, {99}); },
                {"l.opal", "chunk 'ZZZZ'", "zstd level 99"});
    EXPECT_TRUE(dir.entries().empty());
}

TEST(ChunkedFile, ReaderRejectsForeignNewerOlderAndMissingFiles) {
    TempDir dir;
    auto path = dir / "k.opal";
    writeChunkedFile(path, kChunkedKind, {});
    expectError([&] { ChunkedFileReader(path, {"SCAT", {1, 0}}); }, {"k.opal", "'TEST' file, expected 'SCAT'"});
    ChunkedFileReader(path, {"TEST", {1, 0}});  // newer minor: readable
    expectError([&] { ChunkedFileReader(path, {"TEST", {2, 0}}); }, {"k.opal", "format version 1.2 is older", "2.x"});

    std::vector<std::byte> file = test::readBytes(path);
    test::putU16(file, 12, 2);  // major version
    test::resealHeader(file);
    test::writeBytes(path, file);
    expectError([&] { ChunkedFileReader(path, kChunkedKind); }, {"k.opal", "format version 2.2 is newer", "1.x"});

    test::writeBytes(dir / "text.opal", {std::byte('#'), std::byte('u'), std::byte('s'), std::byte('d'),
                                         std::byte('a'), std::byte(' '), std::byte('1'), std::byte('\n')});
    expectError([&] { ChunkedFileReader(dir / "text.opal", kChunkedKind); }, {"text.opal", "not an Opal container"});
    expectError([&] { ChunkedFileReader(dir / "absent.opal", kChunkedKind); }, {"absent.opal", "cannot open"});
}

TEST(ChunkedFile, ReaderRejectsDuplicateAndUnknownRequiredChunks) {
    TempDir dir;
    auto path = dir / "u.opal";
    std::vector<std::byte> a = pattern(10, 5, false);
    writeChunkedFile(path, kChunkedKind, std::vector{bytesChunk("KNWN", ChunkCodec::Raw, a),
                                              bytesChunk("OPTL", ChunkCodec::Raw, a, false),
                                              bytesChunk("NEWR", ChunkCodec::Zstd, a)});
    ChunkedFileReader reader(path, kChunkedKind);
    const ChunkTag known[] = {"KNWN"};
    expectError([&] { reader.rejectUnknownRequired(known); }, {"u.opal", "chunk 'NEWR'", "unknown chunk marked required"});
    const ChunkTag knownAndNew[] = {"KNWN", "NEWR"};
    reader.rejectUnknownRequired(knownAndNew);  // the optional one is ignored
    expectError([&] { reader.open("GONE"); }, {"u.opal", "missing chunk 'GONE'"});

    // Rename the second table entry's tag to the first's (table at the end, 48-byte rows).
    std::vector<std::byte> file = test::readBytes(path);
    std::size_t table = test::getU64(file, 24);
    for (int i = 0; i < 4; ++i) file[table + 48 + i] = file[table + i];
    test::resealTable(file);
    test::writeBytes(path, file);
    expectError([&] { ChunkedFileReader(path, kChunkedKind); }, {"u.opal", "chunk 'KNWN'", "twice"});
}

TEST(ChunkedFile, SourceRefusesOversizedCountsAndLeftoverBytes) {
    TempDir dir;
    auto path = dir / "s.opal";
    std::vector<std::byte> a = pattern(64, 6, false);
    writeChunkedFile(path, kChunkedKind, std::vector{bytesChunk("DATA", ChunkCodec::Zstd, a)});
    ChunkedFileReader reader(path, kChunkedKind);
    ChunkSource source = reader.open("DATA");
    expectError([&] { source.readArray<float>(std::uint64_t(1) << 40, "values"); },
                {"s.opal", "chunk 'DATA'", "values", "do not fit"});
    source.readU32();
    expectError([&] { source.finish(); }, {"s.opal", "chunk 'DATA'", "60 bytes left over"});
}

TEST(ChunkedFile, TableEntriesMustTileTheFile) {
    TempDir dir;
    auto path = dir / "t.opal";
    std::vector<std::byte> a = pattern(32, 7, false), b = pattern(32, 8, false);
    writeChunkedFile(path, kChunkedKind, std::vector{bytesChunk("AAAA", ChunkCodec::Raw, a), bytesChunk("BBBB", ChunkCodec::Raw, b)});
    std::vector<std::byte> file = test::readBytes(path);
    std::size_t table = test::getU64(file, 24);
    test::putU64(file, table + 48 + 8, 64);  // BBBB's offset onto AAAA's bytes
    test::resealTable(file);
    test::writeBytes(path, file);
    expectError([&] { ChunkedFileReader(path, kChunkedKind); }, {"t.opal", "chunk 'BBBB'", "previous chunk ends"});
}

}  // namespace
}  // namespace opal
