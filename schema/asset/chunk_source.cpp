#include "schema/asset/chunk_source.h"

#include "schema/asset/little_endian.h"
#include "schema/error.h"

#include <zstd.h>

#include <array>
#include <cstring>

namespace opal {

void ChunkSource::DCtxDeleter::operator()(ZSTD_DCtx_s* d) const { ZSTD_freeDCtx(d); }

ChunkSource::ChunkSource(std::vector<std::byte> stored, const ChunkInfo& info, std::string context)
    : stored_(std::move(stored)),
      codec_(info.codec),
      rawSize_(info.rawSize),
      rawChecksum_(info.rawChecksum),
      context_(std::move(context)) {
    if (codec_ != ChunkCodec::Zstd) return;
    dctx_.reset(ZSTD_createDCtx());
    if (!dctx_) fail("cannot create a zstd decompression context");
}

ChunkSource::~ChunkSource() = default;
ChunkSource::ChunkSource(ChunkSource&&) noexcept = default;
ChunkSource& ChunkSource::operator=(ChunkSource&&) noexcept = default;

void ChunkSource::fail(std::string_view problem) const {
    throw Error(context_ + ": " + std::string(problem));
}

void ChunkSource::requireBytes(std::uint64_t count, std::size_t elementBytes, std::string_view what) const {
    if (count > remaining() / elementBytes)
        fail(std::string(what) + ": " + std::to_string(count) + " values of " +
             std::to_string(elementBytes) + " bytes do not fit in the " +
             std::to_string(remaining()) + " bytes left in the chunk");
}

void ChunkSource::read(std::span<std::byte> out) {
    if (out.size() > remaining())
        fail("data ends early: " + std::to_string(out.size()) + " more bytes wanted, " +
             std::to_string(remaining()) + " left");
    if (codec_ == ChunkCodec::Raw)
        readRaw(out);
    else
        readZstd(out);
    rawHash_.update(out);
    rawRead_ += out.size();
}

void ChunkSource::readRaw(std::span<std::byte> out) {
    if (out.empty()) return;
    std::memcpy(out.data(), stored_.data() + storedPos_, out.size());
    storedPos_ += out.size();
}

void ChunkSource::readZstd(std::span<std::byte> out) {
    ZSTD_outBuffer buffer{out.data(), out.size(), 0};
    while (buffer.pos < buffer.size) {
        if (frameEnded_) fail("zstd frame decodes to fewer bytes than the table's raw size");
        ZSTD_inBuffer in{stored_.data(), stored_.size(), storedPos_};
        std::size_t before = buffer.pos;
        std::size_t hint = ZSTD_decompressStream(dctx_.get(), &buffer, &in);
        if (ZSTD_isError(hint)) fail(std::string("zstd data corrupt: ") + ZSTD_getErrorName(hint));
        bool progressed = in.pos != storedPos_ || buffer.pos != before;
        storedPos_ = in.pos;
        frameEnded_ = hint == 0;
        if (!progressed && !frameEnded_) fail("zstd frame truncated");
    }
}

// After the last raw byte the frame must end, with nothing behind it.
void ChunkSource::finishZstd() {
    std::array<std::byte, 1> extra{};
    while (!frameEnded_) {
        ZSTD_outBuffer buffer{extra.data(), extra.size(), 0};
        ZSTD_inBuffer in{stored_.data(), stored_.size(), storedPos_};
        std::size_t hint = ZSTD_decompressStream(dctx_.get(), &buffer, &in);
        if (ZSTD_isError(hint)) fail(std::string("zstd data corrupt: ") + ZSTD_getErrorName(hint));
        if (buffer.pos != 0) fail("zstd frame decodes to more bytes than the table's raw size");
        if (in.pos == storedPos_ && hint != 0) fail("zstd frame truncated");
        storedPos_ = in.pos;
        frameEnded_ = hint == 0;
    }
}

void ChunkSource::finish() {
    if (remaining() != 0)
        fail(std::to_string(remaining()) + " bytes left over after the last field (inconsistent sizes)");
    if (codec_ == ChunkCodec::Zstd) finishZstd();
    if (storedPos_ != stored_.size())
        fail(std::to_string(stored_.size() - storedPos_) + " stored bytes after the end of the encoded data");
    if (rawHash_.digest() != rawChecksum_) fail("checksum mismatch (decoded data corrupt)");
}

std::uint32_t ChunkSource::readU32() {
    std::array<std::byte, 4> b;
    read(b);
    return le::get<std::uint32_t>(b, 0);
}

std::uint64_t ChunkSource::readU64() {
    std::array<std::byte, 8> b;
    read(b);
    return le::get<std::uint64_t>(b, 0);
}

double ChunkSource::readF64() { return std::bit_cast<double>(readU64()); }

std::string ChunkSource::readString(std::uint32_t maxBytes, std::string_view what) {
    std::uint32_t length = readU32();
    if (length > maxBytes)
        fail(std::string(what) + ": " + std::to_string(length) + " bytes, more than the " +
             std::to_string(maxBytes) + " allowed");
    requireBytes(length, 1, what);
    std::string s(length, '\0');
    read(std::as_writable_bytes(std::span(s.data(), s.size())));
    return s;
}

}  // namespace opal
