// opal-fuzz-sidecar-to-chunks SIDECAR OUT: writes the chunk list (sidecar_chunk_list.h) of a
// sidecar, each chunk's raw bytes with its codec and flag, as a seed for
// fuzz_sidecar_chunks. Exit status 1 with the reader's message on a bad sidecar.
#include "schema/asset/chunked_file.h"
#include "schema/asset/sidecar.h"
#include "schema/error.h"
#include "tests/fuzz/sidecar_chunk_list.h"

#include <cstdio>
#include <fstream>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s SIDECAR OUT\n", argv[0]);
        return 2;
    }
    try {
        opal::ChunkedFileReader reader(argv[1], opal::kSidecarKind);
        std::vector<std::uint8_t> list;
        for (const opal::ChunkInfo& info : reader.chunks()) {
            opal::ChunkSource source = reader.open(info.tag);
            std::vector<std::byte> raw(source.remaining());
            source.read(raw);
            source.finish();
            std::span<const std::uint8_t> contents(reinterpret_cast<const std::uint8_t*>(raw.data()), raw.size());
            opal::fuzz::appendChunkRecord(list, info.tag, info.codec, info.required, contents);
        }
        std::ofstream out(argv[2], std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(list.data()), static_cast<std::streamsize>(list.size()));
        return out ? 0 : 1;
    } catch (const opal::Error& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
