// The structure-aware sidecar input: a list of chunks that fuzz_sidecar_chunks assembles
// into a well-formed container (magic, header, chunk table, XXH64 checksums, zstd when
// asked), so that mutations of the chunks' contents reach the validators behind the
// checksums instead of stopping at them. Records follow each other to the end:
//   tag      4 bytes
//   flags    1 byte: bit 0 zstd (else raw), bit 1 optional (else required)
//   size     u32 little-endian, clamped to the bytes that remain
//   contents `size` bytes (the chunk's raw bytes)
#pragma once

#include "schema/asset/chunk_format.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace opal::fuzz {

struct ListedChunk {
    ChunkTag tag;
    ChunkCodec codec = ChunkCodec::Raw;
    bool required = true;
    std::span<const std::uint8_t> contents;
};

inline constexpr std::size_t kChunkRecordHeader = 9;

inline std::vector<ListedChunk> parseChunkList(std::span<const std::uint8_t> in) {
    std::vector<ListedChunk> chunks;
    while (in.size() >= kChunkRecordHeader && chunks.size() < container::kMaxChunks) {
        ListedChunk chunk;
        chunk.tag = ChunkTag::fromChars({static_cast<char>(in[0]), static_cast<char>(in[1]),
                                         static_cast<char>(in[2]), static_cast<char>(in[3])});
        chunk.codec = (in[4] & 1) != 0 ? ChunkCodec::Zstd : ChunkCodec::Raw;
        chunk.required = (in[4] & 2) == 0;
        std::size_t size = std::size_t(in[5]) | std::size_t(in[6]) << 8 | std::size_t(in[7]) << 16 |
                           std::size_t(in[8]) << 24;
        in = in.subspan(kChunkRecordHeader);
        size = size < in.size() ? size : in.size();
        chunk.contents = in.first(size);
        in = in.subspan(size);
        chunks.push_back(chunk);
    }
    return chunks;
}

inline void appendChunkRecord(std::vector<std::uint8_t>& out, const ChunkTag& tag, ChunkCodec codec, bool required,
                              std::span<const std::uint8_t> contents) {
    for (char c : tag.chars) {
        out.push_back(static_cast<std::uint8_t>(c));
    }
    out.push_back(static_cast<std::uint8_t>((codec == ChunkCodec::Zstd ? 1 : 0) | (required ? 0 : 2)));
    auto size = static_cast<std::uint32_t>(contents.size());
    for (int shift = 0; shift < 32; shift += 8) {
        out.push_back(static_cast<std::uint8_t>(size >> shift));
    }
    out.insert(out.end(), contents.begin(), contents.end());
}

}  // namespace opal::fuzz
