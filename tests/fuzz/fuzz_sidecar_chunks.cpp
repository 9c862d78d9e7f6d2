// Structure-aware sidecar fuzzing: the input is a chunk list (sidecar_chunk_list.h) that is
// written as a valid 'SCAT' container by Opal's own container writer, then read back with
// readSidecar. Checksums and framing are always right, so every mutation lands in the
// chunk decoders and the sidecar's validators.
#include "schema/asset/chunked_file.h"
#include "schema/asset/sidecar.h"
#include "schema/error.h"
#include "tests/fuzz/fuzz_scratch.h"
#include "tests/fuzz/sidecar_chunk_list.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<opal::ChunkProducer> producers;
    for (const opal::fuzz::ListedChunk& chunk : opal::fuzz::parseChunkList({data, size})) {
        std::span<const std::byte> bytes = std::as_bytes(chunk.contents);
        producers.push_back({chunk.tag, chunk.codec, chunk.required, [bytes](opal::ChunkSink& sink) { sink.write(bytes); }});
    }
    std::filesystem::path path = opal::fuzz::scratch().dir() / "chunks.opal";
    try {
        opal::writeChunkedFile(path, opal::kSidecarKind, producers, {.zstdLevel = 1});
    } catch (const opal::Error&) {
        return 0;  // a list the writer refuses (e.g. a duplicate tag) is no container
    }
    try {
        opal::TranslucentAsset asset;
        opal::readSidecar(path, asset);
    } catch (const opal::Error&) {
    }
    return 0;
}
