// Opal's versioned chunked binary container (docs/ARCHITECTURE.md#asset; byte layout in
// schema/asset/SIDECAR.md): a 64-byte header (magic, kind, version, sizes, checksums), the chunks'
// stored bytes back to back, then the chunk table. Every byte of a file is covered by a
// checksum. Writers replace files atomically; readers validate everything before they
// trust or allocate anything, and every error names the file (and the chunk).
#pragma once

#include "schema/asset/chunk_format.h"
#include "schema/asset/chunk_sink.h"
#include "schema/asset/chunk_source.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

// One chunk to write. `produce` is called while the file is being written and streams the
// chunk's raw bytes into the sink; if it throws, the whole write is abandoned.
struct ChunkProducer {
    ChunkTag tag;
    ChunkCodec codec = ChunkCodec::Zstd;
    bool required = true;
    std::function<void(ChunkSink&)> produce;
};

struct ChunkedFileWriteOptions {
    int zstdLevel = 3;
};

// Writes `chunks` in order to a temporary file beside `path`, fsyncs it and renames it
// over `path`. On any error (including one thrown by a producer) `path` is left as it
// was and the temporary file is removed. Throws opal::Error.
void writeChunkedFile(const std::filesystem::path& path, const FileKind& kind,
                      std::span<const ChunkProducer> chunks,
                      const ChunkedFileWriteOptions& options = {});

// The cap on one file's decoded bytes: $OPAL_SIDECAR_MAX_BYTES, else
// container::kDefaultMaxDecodedBytes. Throws opal::Error when the variable is not a number.
std::uint64_t maxDecodedBytes();

class ChunkedFileReader {
public:
    // Opens `path` and validates its header and chunk table against `supported`: same
    // kind tag, major version not newer. Chunk data is checked when a chunk is opened.
    ChunkedFileReader(std::filesystem::path path, const FileKind& supported);

    const FormatVersion& version() const { return version_; }
    std::span<const ChunkInfo> chunks() const { return chunks_; }
    const ChunkInfo* find(ChunkTag tag) const;

    // Reads the chunk's stored bytes, checks their XXH64 and returns a decoder for them.
    // Throws when the chunk is missing.
    ChunkSource open(ChunkTag tag);

    // Rejects the file if it holds a required chunk whose tag is not in `known` (written
    // by a newer writer that expects readers to understand it).
    void rejectUnknownRequired(std::span<const ChunkTag> known) const;

    const std::filesystem::path& path() const { return path_; }
    [[noreturn]] void fail(std::string_view problem) const;  // "<path>: <problem>"

private:
    std::vector<std::byte> readAt(std::uint64_t offset, std::uint64_t size);
    std::vector<std::byte> readHeaderBytes();
    void checkIdentity(std::span<const std::byte> header, const FileKind& supported);
    void readHeader(const FileKind& supported);
    void readTable(std::uint32_t count, std::uint64_t tableOffset, std::uint64_t tableChecksum);
    ChunkInfo parseEntry(std::span<const std::byte> entry, std::size_t index) const;
    void checkPlacement(std::uint64_t tableOffset) const;
    void checkDecodedTotal() const;

    std::filesystem::path path_;
    std::ifstream stream_;
    std::uint64_t fileSize_ = 0;
    FormatVersion version_;
    std::vector<ChunkInfo> chunks_;
};

// "a.opal: chunk 'TRNS'", the prefix of every message about one chunk.
std::string chunkContext(const std::filesystem::path& path, ChunkTag tag);

}  // namespace opal
