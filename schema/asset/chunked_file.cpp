#include "schema/asset/chunked_file.h"

#include "schema/usd/atomic_file.h"
#include "schema/asset/little_endian.h"
#include "schema/asset/xxhash64.h"
#include "schema/error.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace opal {

using namespace container;

namespace {

// Field offsets inside the 64-byte header (SIDECAR.md).
constexpr std::size_t kKindAt = 8, kMajorAt = 12, kMinorAt = 14, kCountAt = 16;
constexpr std::size_t kTableOffsetAt = 24, kFileSizeAt = 32, kTableChecksumAt = 40;
constexpr std::size_t kHeaderChecksumAt = 56;

void putTag(std::vector<std::byte>& out, ChunkTag tag) {
    for (char c : tag.chars) out.push_back(static_cast<std::byte>(c));
}

ChunkTag getTag(std::span<const std::byte> in, std::size_t offset) {
    std::array<char, 4> c{};
    for (std::size_t i = 0; i < 4; ++i) c[i] = static_cast<char>(in[offset + i]);
    return ChunkTag::fromChars(c);
}

std::vector<std::byte> encodeTable(std::span<const ChunkInfo> chunks) {
    std::vector<std::byte> out;
    for (const ChunkInfo& c : chunks) {
        putTag(out, c.tag);
        le::put(out, static_cast<std::uint8_t>(c.codec));
        le::put(out, static_cast<std::uint8_t>(c.required ? kFlagRequired : 0));
        le::put(out, std::uint16_t(0));
        for (std::uint64_t v : {c.offset, c.storedSize, c.rawSize, c.storedChecksum, c.rawChecksum})
            le::put(out, v);
    }
    return out;
}

std::vector<std::byte> encodeHeader(const FileKind& kind, std::size_t chunkCount,
                                    std::uint64_t tableOffset, std::uint64_t fileSize,
                                    std::uint64_t tableChecksum) {
    std::vector<std::byte> out;
    for (unsigned char m : kMagic) out.push_back(static_cast<std::byte>(m));
    putTag(out, kind.tag);
    le::put(out, kind.version.major);
    le::put(out, kind.version.minor);
    le::put(out, static_cast<std::uint32_t>(chunkCount));
    le::put(out, std::uint32_t(0));
    for (std::uint64_t v : {tableOffset, fileSize, tableChecksum, std::uint64_t(0)}) le::put(out, v);
    le::put(out, xxh64(out));
    return out;
}

void checkChunkList(const std::filesystem::path& path, const FileKind& kind,
                    std::span<const ChunkProducer> chunks) {
    std::string where = path.string() + ": ";
    if (!kind.tag.printable()) throw Error(where + "file kind '" + kind.tag.str() + "' is not printable ASCII");
    if (kind.version.major == 0) throw Error(where + "format major version must be at least 1");
    if (chunks.size() > kMaxChunks)
        throw Error(where + std::to_string(chunks.size()) + " chunks, more than the " +
                    std::to_string(kMaxChunks) + " allowed");
    for (std::size_t i = 0; i < chunks.size(); ++i) {
        if (!chunks[i].tag.printable())
            throw Error(chunkContext(path, chunks[i].tag) + ": tag is not printable ASCII");
        for (std::size_t j = 0; j < i; ++j)
            if (chunks[j].tag == chunks[i].tag)
                throw Error(chunkContext(path, chunks[i].tag) + ": written twice");
    }
}

ChunkInfo writeChunk(AtomicFileWriter& file, const ChunkProducer& producer,
                     const ChunkedFileWriteOptions& options) {
    ChunkInfo info{producer.tag, producer.codec, producer.required, file.size()};
    ChunkSink sink(file, producer.codec, options.zstdLevel, chunkContext(file.target(), producer.tag));
    if (producer.produce) producer.produce(sink);
    ChunkSink::Totals totals = sink.finish();
    if (totals.rawSize > kMaxRawChunkBytes)
        throw Error(sink.context() + ": " + std::to_string(totals.rawSize) +
                    " bytes, more than readers accept");
    info.storedSize = totals.storedSize;
    info.rawSize = totals.rawSize;
    info.storedChecksum = totals.storedChecksum;
    info.rawChecksum = totals.rawChecksum;
    return info;
}

}  // namespace

std::string chunkContext(const std::filesystem::path& path, ChunkTag tag) {
    return path.string() + ": chunk '" + tag.str() + "'";
}

void writeChunkedFile(const std::filesystem::path& path, const FileKind& kind,
                      std::span<const ChunkProducer> chunks, const ChunkedFileWriteOptions& options) {
    checkChunkList(path, kind, chunks);
    AtomicFileWriter file(path);
    file.append(std::vector<std::byte>(kHeaderBytes));  // placeholder until the sizes are known
    std::vector<ChunkInfo> table;
    for (const ChunkProducer& producer : chunks) table.push_back(writeChunk(file, producer, options));
    std::uint64_t tableOffset = file.size();
    std::vector<std::byte> tableBytes = encodeTable(table);
    file.append(tableBytes);
    file.overwrite(0, encodeHeader(kind, table.size(), tableOffset, file.size(), xxh64(tableBytes)));
    file.commit();
}

// ---------------------------------------------------------------------------------------

ChunkedFileReader::ChunkedFileReader(std::filesystem::path path, const FileKind& supported)
    : path_(std::move(path)) {
    std::error_code error;
    fileSize_ = std::filesystem::file_size(path_, error);
    if (error) fail("cannot open: " + error.message());
    stream_.open(path_, std::ios::binary);
    if (!stream_) fail(std::string("cannot open: ") + std::strerror(errno));
    readHeader(supported);
}

void ChunkedFileReader::fail(std::string_view problem) const {
    throw Error(path_.string() + ": " + std::string(problem));
}

std::vector<std::byte> ChunkedFileReader::readAt(std::uint64_t offset, std::uint64_t size) {
    std::vector<std::byte> bytes(static_cast<std::size_t>(size));
    stream_.clear();
    stream_.seekg(static_cast<std::streamoff>(offset));
    stream_.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size));
    if (!stream_ || static_cast<std::uint64_t>(stream_.gcount()) != size)
        fail("read error at byte " + std::to_string(offset) + " (file changed while reading?)");
    return bytes;
}

std::vector<std::byte> ChunkedFileReader::readHeaderBytes() {
    if (fileSize_ < kMagic.size())
        fail("not an Opal container: " + std::to_string(fileSize_) + " bytes, too short for its magic number");
    std::vector<std::byte> h = readAt(0, std::min<std::uint64_t>(fileSize_, kHeaderBytes));
    if (std::memcmp(h.data(), kMagic.data(), kMagic.size()) != 0)
        fail("not an Opal container (bad magic number, or damaged by a text-mode transfer)");
    if (fileSize_ < kHeaderBytes)
        fail("truncated: " + std::to_string(fileSize_) + " bytes, shorter than the 64-byte header");
    return h;
}

// The 64-byte header's layout is frozen across versions, so its checksum is checked
// first: a damaged version field is reported as damage, not as a newer format.
void ChunkedFileReader::checkIdentity(std::span<const std::byte> h, const FileKind& supported) {
    if (xxh64(h.first(kHeaderChecksumAt)) != le::get<std::uint64_t>(h, kHeaderChecksumAt))
        fail("header: checksum mismatch (header corrupt)");
    ChunkTag kind = getTag(h, kKindAt);
    if (!(kind == supported.tag))
        fail("header: a '" + kind.str() + "' file, expected '" + supported.tag.str() + "'");
    version_ = {le::get<std::uint16_t>(h, kMajorAt), le::get<std::uint16_t>(h, kMinorAt)};
    if (version_.major == 0) fail("header: invalid format version " + version_.str());
    if (version_.major > supported.version.major)
        fail("header: format version " + version_.str() + " is newer than this Opal reads (" +
             std::to_string(supported.version.major) + ".x); update Opal");
    if (version_.major < supported.version.major)
        fail("header: format version " + version_.str() + " is older than this Opal reads (" +
             std::to_string(supported.version.major) + ".x); write the file again with this Opal");
}

void ChunkedFileReader::readHeader(const FileKind& supported) {
    std::vector<std::byte> h = readHeaderBytes();
    checkIdentity(h, supported);
    std::uint64_t declaredSize = le::get<std::uint64_t>(h, kFileSizeAt);
    if (declaredSize != fileSize_)
        fail("file is " + std::to_string(fileSize_) + " bytes but its header says " +
             std::to_string(declaredSize) + " (truncated or appended to)");
    readTable(le::get<std::uint32_t>(h, kCountAt), le::get<std::uint64_t>(h, kTableOffsetAt),
              le::get<std::uint64_t>(h, kTableChecksumAt));
}

void ChunkedFileReader::readTable(std::uint32_t count, std::uint64_t tableOffset,
                                  std::uint64_t tableChecksum) {
    if (count > kMaxChunks)
        fail("chunk table: " + std::to_string(count) + " chunks, more than the " +
             std::to_string(kMaxChunks) + " allowed");
    std::uint64_t tableBytes = std::uint64_t(count) * kTableEntryBytes;
    if (tableOffset < kHeaderBytes || tableOffset > fileSize_ || fileSize_ - tableOffset != tableBytes)
        fail("chunk table: " + std::to_string(count) + " entries at byte " + std::to_string(tableOffset) +
             " do not end at the end of the file");
    std::vector<std::byte> table = readAt(tableOffset, tableBytes);
    if (xxh64(table) != tableChecksum) fail("chunk table: checksum mismatch (table corrupt)");
    for (std::size_t i = 0; i < count; ++i)
        chunks_.push_back(parseEntry(std::span(table).subspan(i * kTableEntryBytes, kTableEntryBytes), i));
    checkPlacement(tableOffset);
}

ChunkInfo ChunkedFileReader::parseEntry(std::span<const std::byte> e, std::size_t index) const {
    ChunkInfo c;
    c.tag = getTag(e, 0);
    if (!c.tag.printable())
        fail("chunk table entry " + std::to_string(index) + ": tag '" + c.tag.str() + "' is not printable ASCII");
    std::string where = chunkContext(path_, c.tag) + ": ";
    auto codec = le::get<std::uint8_t>(e, 4);
    if (codec > static_cast<std::uint8_t>(ChunkCodec::Zstd))
        throw Error(where + "unknown codec " + std::to_string(codec));
    c.codec = static_cast<ChunkCodec>(codec);
    c.required = (le::get<std::uint8_t>(e, 5) & kFlagRequired) != 0;
    c.offset = le::get<std::uint64_t>(e, 8);
    c.storedSize = le::get<std::uint64_t>(e, 16);
    c.rawSize = le::get<std::uint64_t>(e, 24);
    c.storedChecksum = le::get<std::uint64_t>(e, 32);
    c.rawChecksum = le::get<std::uint64_t>(e, 40);
    return c;
}

// Chunks lie back to back from the end of the header to the table, in table order, each
// tag once, with sizes a real encoder can produce: no byte of the file escapes a checksum.
void ChunkedFileReader::checkPlacement(std::uint64_t tableOffset) const {
    std::uint64_t expected = kHeaderBytes;
    for (std::size_t i = 0; i < chunks_.size(); ++i) {
        const ChunkInfo& c = chunks_[i];
        std::string where = chunkContext(path_, c.tag) + ": ";
        for (std::size_t j = 0; j < i; ++j)
            if (chunks_[j].tag == c.tag) throw Error(where + "appears twice in the chunk table");
        if (c.offset != expected || c.storedSize > tableOffset - expected)
            throw Error(where + "bytes " + std::to_string(c.offset) + " + " + std::to_string(c.storedSize) +
                        " are not where the previous chunk ends (" + std::to_string(expected) +
                        ") or run past the chunk table");
        expected += c.storedSize;
        if (c.rawSize > kMaxRawChunkBytes)
            throw Error(where + "raw size " + std::to_string(c.rawSize) + " exceeds the 64 GiB limit");
        if (c.codec == ChunkCodec::Raw && c.rawSize != c.storedSize)
            throw Error(where + "uncompressed, yet raw size " + std::to_string(c.rawSize) +
                        " differs from stored size " + std::to_string(c.storedSize));
        if (c.codec == ChunkCodec::Zstd && (c.rawSize + kMaxZstdExpansion - 1) / kMaxZstdExpansion > c.storedSize)
            throw Error(where + "raw size " + std::to_string(c.rawSize) + " is more than zstd can expand " +
                        std::to_string(c.storedSize) + " stored bytes to");
    }
    if (expected != tableOffset)
        fail("chunk table: chunks end at byte " + std::to_string(expected) + ", the table starts at " +
             std::to_string(tableOffset));
    checkDecodedTotal();
}

// The sum of the chunks' raw sizes against the cap (chunk_format.h), before any chunk is
// decoded: each raw size was checked against what its stored bytes can expand to above.
void ChunkedFileReader::checkDecodedTotal() const {
    const std::uint64_t cap = maxDecodedBytes();
    std::uint64_t total = 0;
    for (const ChunkInfo& c : chunks_) total += c.rawSize;  // each <= 2^36, at most 1024: no overflow
    if (total > cap)
        fail("chunk table: the chunks decode to " + std::to_string(total) + " bytes, more than the " +
             std::to_string(cap) + " a reader accepts (raise it with " + kMaxDecodedBytesVariable +
             " if this file is genuine)");
}

std::uint64_t maxDecodedBytes() {
    const char* text = std::getenv(kMaxDecodedBytesVariable);
    if (!text || !*text) return kDefaultMaxDecodedBytes;
    char* end = nullptr;
    errno = 0;
    const unsigned long long value = std::strtoull(text, &end, 10);
    if (errno != 0 || *end != '\0' || *text == '-')
        throw Error(std::string(kMaxDecodedBytesVariable) + " = '" + text + "' is not a byte count");
    return value;
}

const ChunkInfo* ChunkedFileReader::find(ChunkTag tag) const {
    auto it = std::find_if(chunks_.begin(), chunks_.end(), [&](const ChunkInfo& c) { return c.tag == tag; });
    return it == chunks_.end() ? nullptr : &*it;
}

ChunkSource ChunkedFileReader::open(ChunkTag tag) {
    const ChunkInfo* info = find(tag);
    if (!info) fail("missing chunk '" + tag.str() + "'");
    std::string context = chunkContext(path_, tag);
    std::vector<std::byte> stored = readAt(info->offset, info->storedSize);
    if (xxh64(stored) != info->storedChecksum)
        throw Error(context + ": checksum mismatch (stored data corrupt)");
    return ChunkSource(std::move(stored), *info, std::move(context));
}

void ChunkedFileReader::rejectUnknownRequired(std::span<const ChunkTag> known) const {
    for (const ChunkInfo& c : chunks_) {
        if (!c.required || std::find(known.begin(), known.end(), c.tag) != known.end()) continue;
        throw Error(chunkContext(path_, c.tag) +
                    ": unknown chunk marked required (written by a newer Opal?); update Opal");
    }
}

}  // namespace opal
