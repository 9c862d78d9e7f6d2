// The reading end of one chunk. It is handed the chunk's stored bytes after the reader has
// checked their XXH64, decodes them on demand into the caller's buffers (so big arrays
// are decompressed straight into their final vectors), hashes the raw bytes as they come
// out, and in finish() checks that the chunk was consumed exactly and that the raw
// checksum matches. Every error names the file and the chunk.
#pragma once

#include "schema/asset/chunk_format.h"
#include "schema/asset/xxhash64.h"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

struct ZSTD_DCtx_s;

namespace opal {

class ChunkSource {
public:
    // context: "a.opal: chunk 'TRNS'".
    ChunkSource(std::vector<std::byte> stored, const ChunkInfo& info, std::string context);
    ~ChunkSource();
    ChunkSource(ChunkSource&&) noexcept;
    ChunkSource& operator=(ChunkSource&&) noexcept;

    // Raw bytes not read yet.
    std::uint64_t remaining() const { return rawSize_ - rawRead_; }

    void read(std::span<std::byte> out);
    std::uint32_t readU32();
    std::uint64_t readU64();
    double readF64();
    std::string readString(std::uint32_t maxBytes, std::string_view what);

    // `count` little-endian numbers. Refuses, before allocating, counts the chunk's
    // remaining bytes cannot hold, so a corrupt count never causes a huge allocation.
    template <class T>
    std::vector<T> readArray(std::uint64_t count, std::string_view what) {
        static_assert(std::is_arithmetic_v<T>);
        static_assert(std::endian::native == std::endian::little,
                      "arrays are read as their in-memory bytes: byte-swap here on big-endian hosts");
        requireBytes(count, sizeof(T), what);
        std::vector<T> values(static_cast<std::size_t>(count));
        read(std::as_writable_bytes(std::span(values)));
        return values;
    }

    // Throws unless `count` values of `elementBytes` fit in the bytes left.
    void requireBytes(std::uint64_t count, std::size_t elementBytes, std::string_view what) const;

    // All raw bytes consumed, the stored encoding ended exactly there, raw XXH64 matches.
    void finish();

    [[noreturn]] void fail(std::string_view problem) const;
    const std::string& context() const { return context_; }

private:
    void readRaw(std::span<std::byte> out);
    void readZstd(std::span<std::byte> out);
    void finishZstd();

    struct DCtxDeleter {
        void operator()(ZSTD_DCtx_s* d) const;
    };

    std::vector<std::byte> stored_;
    ChunkCodec codec_;
    std::uint64_t rawSize_ = 0, rawRead_ = 0, rawChecksum_ = 0;
    std::size_t storedPos_ = 0;
    bool frameEnded_ = false;
    std::string context_;
    std::unique_ptr<ZSTD_DCtx_s, DCtxDeleter> dctx_;
    Xxh64 rawHash_;
};

}  // namespace opal
