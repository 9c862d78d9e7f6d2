// The on-disk vocabulary of Opal's chunked container (byte layout: SIDECAR.md): chunk
// tags, codecs, the per-chunk table entry, file kinds and versions, and the sanity limits
// a reader enforces before it allocates anything a corrupt header asks for.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

namespace opal {

// Four printable ASCII characters naming a chunk ("TRNS") or a kind of file ("SCAT").
struct ChunkTag {
    std::array<char, 4> chars{};

    constexpr ChunkTag() = default;
    constexpr ChunkTag(const char (&literal)[5])  // NOLINT: implicit from "TRNS" on purpose
        : chars{literal[0], literal[1], literal[2], literal[3]} {}
    static constexpr ChunkTag fromChars(std::array<char, 4> c) {
        ChunkTag tag;
        tag.chars = c;
        return tag;
    }

    bool printable() const {
        for (char c : chars)
            if (c < 0x20 || c > 0x7E) return false;
        return true;
    }
    // The tag as text; non-printable bytes as \xNN so that messages stay readable.
    std::string str() const;
    friend bool operator==(const ChunkTag&, const ChunkTag&) = default;
};

enum class ChunkCodec : std::uint8_t { Raw = 0, Zstd = 1 };

struct FormatVersion {
    std::uint16_t major = 1;
    std::uint16_t minor = 0;
    std::string str() const { return std::to_string(major) + "." + std::to_string(minor); }
};

// What a file is: a kind tag plus the version of that kind's layout. Readers accept any
// minor version of a major they know (minor versions only add optional chunks) and
// reject newer majors.
struct FileKind {
    ChunkTag tag;
    FormatVersion version;
};

// One row of the chunk table.
struct ChunkInfo {
    ChunkTag tag;
    ChunkCodec codec = ChunkCodec::Raw;
    bool required = true;  // a reader that does not know the tag must reject the file
    std::uint64_t offset = 0;
    std::uint64_t storedSize = 0;  // bytes in the file
    std::uint64_t rawSize = 0;     // bytes after decoding
    std::uint64_t storedChecksum = 0;  // XXH64 of the stored bytes
    std::uint64_t rawChecksum = 0;     // XXH64 of the raw bytes
};

namespace container {

// PNG-style: a high-bit byte catches 7-bit channels, CR LF catches CR LF -> LF, the lone
// LF catches LF -> CR LF, 0x1A stops `type` on DOS.
inline constexpr std::array<unsigned char, 8> kMagic = {0x89, 'O', 'P', 'L', '\r', '\n', 0x1A, '\n'};
inline constexpr std::size_t kHeaderBytes = 64;
inline constexpr std::size_t kTableEntryBytes = 48;
inline constexpr std::uint32_t kMaxChunks = 1024;
// Largest raw chunk a reader accepts (64 GiB), and zstd's largest possible expansion: a
// block holds at most 128 KiB and its smallest encoding (RLE) is 4 bytes.
inline constexpr std::uint64_t kMaxRawChunkBytes = std::uint64_t(1) << 36;
inline constexpr std::uint64_t kMaxZstdExpansion = 32768;
inline constexpr std::uint8_t kFlagRequired = 1;

// The most decoded bytes a reader accepts for all chunks of one file together, before it
// allocates any of them: 8 GiB by default, which a few-megabyte file could otherwise claim
// through zstd's largest expansion. Bigger bakes raise it with the environment variable
// OPAL_SIDECAR_MAX_BYTES (a byte count, SIDECAR.md "Limits").
inline constexpr std::uint64_t kDefaultMaxDecodedBytes = std::uint64_t(8) << 30;
inline constexpr const char* kMaxDecodedBytesVariable = "OPAL_SIDECAR_MAX_BYTES";

}  // namespace container

inline std::string ChunkTag::str() const {
    static constexpr char kHex[] = "0123456789ABCDEF";
    std::string text;
    for (char c : chars) {
        auto u = static_cast<unsigned char>(c);
        if (u >= 0x20 && u <= 0x7E) {
            text += c;
        } else {
            text += "\\x";
            text += kHex[u >> 4];
            text += kHex[u & 15];
        }
    }
    return text;
}

}  // namespace opal
