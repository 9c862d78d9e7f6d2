// The writing end of one chunk: takes the chunk's raw bytes piece by piece, encodes them
// (raw or zstd, single-threaded so the output is deterministic) straight into the file,
// and hashes both the raw and the stored bytes on the way. Nothing is buffered beyond
// zstd's window and a small staging buffer for scalar fields, so a 100 MB transfer
// matrix is compressed directly from its vectors.
#pragma once

#include "schema/usd/atomic_file.h"
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

struct ZSTD_CCtx_s;

namespace opal {

class ChunkSink {
public:
    // context names the file and chunk in error messages: "a.opal: chunk 'TRNS'".
    ChunkSink(AtomicFileWriter& file, ChunkCodec codec, int zstdLevel, std::string context);
    ~ChunkSink();
    ChunkSink(const ChunkSink&) = delete;
    ChunkSink& operator=(const ChunkSink&) = delete;

    void write(std::span<const std::byte> bytes);
    void writeU32(std::uint32_t v);
    void writeU64(std::uint64_t v);
    void writeF64(double v);
    void writeString(std::string_view s);  // u32 byte length, then UTF-8 bytes

    // An array of fixed-width numbers, little-endian, without its length (write that
    // first where the reader needs it).
    template <class T>
    void writeArray(std::span<const T> values) {
        static_assert(std::is_arithmetic_v<T>);
        static_assert(std::endian::native == std::endian::little,
                      "arrays are written as their in-memory bytes: byte-swap here on big-endian hosts");
        write(std::as_bytes(values));
    }

    struct Totals {
        std::uint64_t storedSize = 0, rawSize = 0;
        std::uint64_t storedChecksum = 0, rawChecksum = 0;
    };
    // Ends the chunk (flushes the zstd frame) and reports its sizes and checksums.
    Totals finish();

    const std::string& context() const { return context_; }

private:
    void flushStaging();
    void encode(std::span<const std::byte> bytes);
    void emit(std::span<const std::byte> stored);
    void compress(std::span<const std::byte> bytes, int endDirective);

    struct CCtxDeleter {
        void operator()(ZSTD_CCtx_s* c) const;
    };

    AtomicFileWriter& file_;
    ChunkCodec codec_;
    std::string context_;
    std::unique_ptr<ZSTD_CCtx_s, CCtxDeleter> cctx_;
    std::vector<std::byte> staging_;
    std::vector<std::byte> compressed_;
    Xxh64 rawHash_, storedHash_;
    std::uint64_t rawSize_ = 0, storedSize_ = 0;
    bool finished_ = false;
};

}  // namespace opal
