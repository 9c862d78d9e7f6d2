// readShadowFieldFile: decode each chunk, checking counts before allocating and the
// field's rules after decoding, so that nothing a corrupt file claims is trusted.
#include "schema/asset/array_codec.h"
#include "schema/asset/chunked_file.h"
#include "schema/asset/shadow_field_checks.h"
#include "schema/asset/shadow_field_file.h"
#include "schema/asset/sidecar_checks.h"

namespace opal {
namespace {

using namespace shadow_field_chunk;

constexpr ChunkTag kKnownChunks[] = {kHeader, kRadii, kMaps, kBakeId, kViews};

void readHeader(ChunkSource src, ShadowField& f) {
    f.name = src.readString(sidecar::kMaxNameBytes, "light name");
    for (int i = 0; i < 3; ++i) f.centre[i] = src.readF64();
    f.emitterRadius = src.readF64();
    const std::uint32_t shells = src.readU32();
    f.directionFaceSize = src.readU32();
    f.mapFaceSize = src.readU32();
    f.keptEnergy = src.readF64();
    src.finish();
    f.radii.assign(shells, 0.0);  // the count, for the checks; RADI fills the values
    shadow_field::checkHeader(f, src.context());
}

void readRadii(ChunkSource src, ShadowField& f) {
    f.radii = src.readArray<double>(f.radii.size(), "shell radii");
    src.finish();
    shadow_field::checkRadii(f, src.context());
}

void readMaps(ChunkSource src, ShadowField& f) {
    const std::uint64_t maps = src.readU64();
    if (maps != f.maps())
        src.fail(std::to_string(maps) + " maps, the header's shells x directions make " + std::to_string(f.maps()));
    const std::uint64_t entries = src.readU64();
    f.offsets = src.readArray<std::uint64_t>(maps + 1, "map offsets");
    sidecar::checkOffsets<std::uint64_t>(f.offsets, maps, entries, src.context(), "map offsets");
    f.indices = readRowDeltas<std::uint64_t>(src, f.offsets, "coefficient indices");
    f.values = readHalfPlanes(src, 3 * entries, "coefficient values");
    src.finish();
    shadow_field::checkMaps(f, src.context());
}

void readViews(ChunkSource src, ShadowField& f) {
    EmitterViews& v = f.views;
    v.directionFaceSize = src.readU32();
    v.imageSize = src.readU32();
    shadow_field::checkViewSizes(v, src.context());  // before the values are allocated
    v.radiance = readHalfPlanes(src, v.values(), "view radiance");
    src.finish();
    shadow_field::checkViews(f, src.context());
}

std::uint64_t readBakeId(ChunkSource src) {
    const std::uint64_t id = src.readU64();
    src.finish();
    return id;
}

}  // namespace

ShadowField readShadowFieldFile(const std::filesystem::path& path) {
    ChunkedFileReader file(path, kShadowFieldKind);
    file.rejectUnknownRequired(kKnownChunks);
    ShadowField f;
    readHeader(file.open(kHeader), f);
    readRadii(file.open(kRadii), f);
    readMaps(file.open(kMaps), f);
    if (file.find(kViews)) readViews(file.open(kViews), f);
    if (file.find(kBakeId)) f.bakeId = readBakeId(file.open(kBakeId));
    return f;
}

}  // namespace opal
