// writeShadowFieldFile: validate everything first, then stream each chunk into the container.
#include "schema/asset/array_codec.h"
#include "schema/asset/chunked_file.h"
#include "schema/asset/shadow_field_checks.h"
#include "schema/asset/shadow_field_file.h"

namespace opal {
namespace {

using namespace shadow_field_chunk;

std::string writeContext(const std::filesystem::path& path, ChunkTag tag) {
    return chunkContext(path, tag) + " (not written)";
}

void writeHeader(ChunkSink& sink, const ShadowField& f) {
    sink.writeString(f.name);
    for (int i = 0; i < 3; ++i) sink.writeF64(f.centre[i]);
    sink.writeF64(f.emitterRadius);
    sink.writeU32(f.shells());
    sink.writeU32(f.directionFaceSize);
    sink.writeU32(f.mapFaceSize);
    sink.writeF64(f.keptEnergy);
}

void writeMaps(ChunkSink& sink, const ShadowField& f) {
    sink.writeU64(f.maps());
    sink.writeU64(f.indices.size());
    sink.writeArray<std::uint64_t>(f.offsets);
    writeRowDeltas<std::uint64_t>(sink, f.offsets, f.indices);
    writeHalfPlanes(sink, f.values);
}

void writeViews(ChunkSink& sink, const EmitterViews& v) {
    sink.writeU32(v.directionFaceSize);
    sink.writeU32(v.imageSize);
    writeHalfPlanes(sink, v.radiance);
}

}  // namespace

void writeShadowFieldFile(const std::filesystem::path& path, const ShadowField& f) {
    shadow_field::checkHeader(f, writeContext(path, kHeader));
    shadow_field::checkRadii(f, writeContext(path, kRadii));
    shadow_field::checkMaps(f, writeContext(path, kMaps));
    if (!f.views.empty()) shadow_field::checkViews(f, writeContext(path, kViews));
    std::vector<ChunkProducer> chunks = {
        {kHeader, ChunkCodec::Raw, true, [&](ChunkSink& s) { writeHeader(s, f); }},
        {kRadii, ChunkCodec::Raw, true, [&](ChunkSink& s) { s.writeArray<double>(f.radii); }},
        {kMaps, ChunkCodec::Zstd, true, [&](ChunkSink& s) { writeMaps(s, f); }},
    };
    if (!f.views.empty())
        chunks.push_back({kViews, ChunkCodec::Zstd, false, [&](ChunkSink& s) { writeViews(s, f.views); }});
    if (f.bakeId) chunks.push_back({kBakeId, ChunkCodec::Raw, false, [&](ChunkSink& s) { s.writeU64(*f.bakeId); }});
    writeChunkedFile(path, kShadowFieldKind, chunks);
}

}  // namespace opal
