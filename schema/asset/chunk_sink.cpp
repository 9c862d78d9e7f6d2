#include "schema/asset/chunk_sink.h"

#include "schema/asset/little_endian.h"
#include "schema/error.h"

#include <zstd.h>

namespace opal {
namespace {

constexpr std::size_t kStagingBytes = 64 * 1024;

}  // namespace

void ChunkSink::CCtxDeleter::operator()(ZSTD_CCtx_s* c) const { ZSTD_freeCCtx(c); }

ChunkSink::ChunkSink(AtomicFileWriter& file, ChunkCodec codec, int zstdLevel, std::string context)
    : file_(file), codec_(codec), context_(std::move(context)) {
    staging_.reserve(kStagingBytes);
    if (codec_ != ChunkCodec::Zstd) return;
    if (zstdLevel < ZSTD_minCLevel() || zstdLevel > ZSTD_maxCLevel())
        throw Error(context_ + ": zstd level " + std::to_string(zstdLevel) + " outside [" +
                    std::to_string(ZSTD_minCLevel()) + ", " + std::to_string(ZSTD_maxCLevel()) + "]");
    cctx_.reset(ZSTD_createCCtx());
    if (!cctx_) throw Error(context_ + ": cannot create a zstd compression context");
    // Deterministic output: single-threaded; no content checksum (the table has XXH64s).
    ZSTD_CCtx_setParameter(cctx_.get(), ZSTD_c_compressionLevel, zstdLevel);
    ZSTD_CCtx_setParameter(cctx_.get(), ZSTD_c_nbWorkers, 0);
    ZSTD_CCtx_setParameter(cctx_.get(), ZSTD_c_checksumFlag, 0);
    compressed_.resize(ZSTD_CStreamOutSize());
}

ChunkSink::~ChunkSink() = default;

void ChunkSink::write(std::span<const std::byte> bytes) {
    if (staging_.size() + bytes.size() > kStagingBytes) flushStaging();
    if (bytes.size() >= kStagingBytes) {
        encode(bytes);
        return;
    }
    staging_.insert(staging_.end(), bytes.begin(), bytes.end());
}

void ChunkSink::writeU32(std::uint32_t v) {
    std::vector<std::byte> b;
    le::put(b, v);
    write(b);
}

void ChunkSink::writeU64(std::uint64_t v) {
    std::vector<std::byte> b;
    le::put(b, v);
    write(b);
}

void ChunkSink::writeF64(double v) {
    std::vector<std::byte> b;
    le::putF64(b, v);
    write(b);
}

void ChunkSink::writeString(std::string_view s) {
    if (s.size() > UINT32_MAX) throw Error(context_ + ": string longer than 4 GiB");
    writeU32(static_cast<std::uint32_t>(s.size()));
    write(std::as_bytes(std::span(s.data(), s.size())));
}

void ChunkSink::flushStaging() {
    if (staging_.empty()) return;
    encode(staging_);
    staging_.clear();
}

void ChunkSink::encode(std::span<const std::byte> bytes) {
    rawHash_.update(bytes);
    rawSize_ += bytes.size();
    if (codec_ == ChunkCodec::Raw)
        emit(bytes);
    else
        compress(bytes, ZSTD_e_continue);
}

void ChunkSink::emit(std::span<const std::byte> stored) {
    file_.append(stored);
    storedHash_.update(stored);
    storedSize_ += stored.size();
}

// Feeds `bytes` to zstd and writes whatever it outputs; with ZSTD_e_end, loops until the
// frame is complete.
void ChunkSink::compress(std::span<const std::byte> bytes, int endDirective) {
    auto directive = static_cast<ZSTD_EndDirective>(endDirective);
    ZSTD_inBuffer in{bytes.data(), bytes.size(), 0};
    for (;;) {
        ZSTD_outBuffer out{compressed_.data(), compressed_.size(), 0};
        std::size_t left = ZSTD_compressStream2(cctx_.get(), &out, &in, directive);
        if (ZSTD_isError(left))
            throw Error(context_ + ": zstd compression failed: " + ZSTD_getErrorName(left));
        emit(std::span(compressed_.data(), out.pos));
        bool done = directive == ZSTD_e_end ? left == 0 : in.pos == in.size;
        if (done) return;
    }
}

ChunkSink::Totals ChunkSink::finish() {
    if (finished_) throw Error(context_ + ": internal error: chunk finished twice");
    flushStaging();
    if (codec_ == ChunkCodec::Zstd) compress({}, ZSTD_e_end);
    finished_ = true;
    return {storedSize_, rawSize_, storedHash_.digest(), rawHash_.digest()};
}

}  // namespace opal
