// writeSidecar: validate everything first, then stream each chunk into the container.
#include "schema/asset/array_codec.h"
#include "schema/asset/chunked_file.h"
#include "schema/asset/normal_harmonics.h"
#include "schema/asset/sidecar.h"
#include "schema/asset/sidecar_checks.h"
#include "schema/asset/transfer_value_grid.h"

namespace opal {
namespace {

using namespace sidecar_chunk;

std::string writeContext(const std::filesystem::path& path, ChunkTag tag) {
    return chunkContext(path, tag) + " (not written)";
}

ChunkTag harmonicsChunk(const CompressedTransfer& t) {
    return t.harmonicSet.count == kNormalHarmonics ? kHarmonics : kPositionHarmonics;
}

void validate(const std::filesystem::path& path, const TranslucentAsset& a) {
    sidecar::checkName(a.name, writeContext(path, kHeader));
    sidecar::checkUnitsPerMm(a.unitsPerMm, writeContext(path, kHeader));
    sidecar::checkLayout(a.layout, writeContext(path, kLayout));
    std::uint64_t samples = a.layout.cells();
    sidecar::checkSamples(a.samples, samples, writeContext(path, kSamples));
    sidecar::checkVertexWeights(a.vertexWeights, samples, writeContext(path, kVertexWeights));
    sidecar::checkTransfer(a.transfer, samples, writeContext(path, kTransfer));
    sidecar::checkHarmonics(a.transfer, samples, writeContext(path, harmonicsChunk(a.transfer)));
    sidecar::checkEnvironment(a.environment, samples, writeContext(path, kEnvironment));
}

void writeHeader(ChunkSink& sink, const TranslucentAsset& a) {
    sink.writeString(a.name);
    sink.writeF64(a.unitsPerMm);
    sink.writeU64(a.layout.cells());
    sink.writeU32(static_cast<std::uint32_t>(a.transfer.perBasis.size()));
    sink.writeU32(static_cast<std::uint32_t>(a.vertexWeights.offsets.size() - 1));
    sink.writeU64(meshTopologyHash(a.mesh));
}

void writeLayout(ChunkSink& sink, const ChartLayout& layout) {
    sink.writeU32(layout.charts);
    sink.writeU32(layout.log2Size);
}

// Structure of arrays (positions, normals, areas) compresses better than records.
void writeSamples(ChunkSink& sink, const std::vector<SurfaceSample>& samples) {
    std::vector<float> positions, normals, areas;
    for (const SurfaceSample& s : samples) {
        positions.insert(positions.end(), {s.position.x, s.position.y, s.position.z});
        normals.insert(normals.end(), {s.normal.x, s.normal.y, s.normal.z});
        areas.push_back(s.area);
    }
    sink.writeU64(samples.size());
    writeFloatPlanes(sink, positions);
    writeFloatPlanes(sink, normals);
    writeFloatPlanes(sink, areas);
}

void writeVertexWeights(ChunkSink& sink, const VertexWeights& w) {
    sink.writeU32(static_cast<std::uint32_t>(w.offsets.size() - 1));
    sink.writeU64(w.samples.size());
    sink.writeArray<std::uint32_t>(w.offsets);
    writeRowDeltas<std::uint32_t>(sink, w.offsets, w.samples);
    writeFloatPlanes(sink, w.weights);
}

// Values on the matrix's grid (transfer_value_grid.h), or exactly for step 0.
void writeMatrixValues(ChunkSink& sink, const SparseMatrix& m, double step, const TransferValueGrid& grid) {
    sink.writeF64(step);
    if (step == 0.0) return writeFloatPlanes(sink, m.values);
    writeVarints(sink, grid.quantize(m, step));
}

void writeMatrix(ChunkSink& sink, const SparseMatrix& m, double step, const TransferValueGrid& grid) {
    sink.writeU32(m.rows);
    sink.writeU32(m.cols);
    sink.writeU64(m.columns.size());
    sink.writeArray<std::uint64_t>(m.rowOffsets);
    writeRowDeltas<std::uint64_t>(sink, m.rowOffsets, m.columns);
    writeMatrixValues(sink, m, step, grid);
}

void writeTransfer(ChunkSink& sink, const CompressedTransfer& t, const ChartLayout& layout) {
    sink.writeU32(static_cast<std::uint32_t>(t.perBasis.size()));
    sink.writeF64(t.keepFraction);
    sink.writeF64(t.energyFraction);
    const TransferValueGrid grid(layout);
    for (std::size_t k = 0; k < t.perBasis.size(); ++k) writeMatrix(sink, t.perBasis[k], t.valueStep(k), grid);
}

// HARM (9 functions) or HARP (36, with the set's frame).
void writeHarmonics(ChunkSink& sink, const CompressedTransfer& t, std::uint64_t samples) {
    sink.writeU32(t.harmonicSet.count);
    sink.writeU32(std::uint32_t(t.perBasis.size()));
    sink.writeU64(samples);
    if (t.harmonicSet.count != kNormalHarmonics) {
        for (int a = 0; a < 3; ++a) sink.writeF64(t.harmonicSet.centre[a]);
        sink.writeF64(t.harmonicSet.inverseScale);
    }
    writeFloatPlanes(sink, t.harmonics);
}

void writeEnvironment(ChunkSink& sink, const EnvironmentTransfer& env, std::uint64_t samples) {
    sink.writeU32(env.cubeFaceSize);
    sink.writeU32(env.fresnelTerms);
    sink.writeU64(sidecar::environmentRows(env, samples));
    sink.writeU64(env.indices.size());
    sink.writeArray<std::uint32_t>(env.offsets);
    writeRowDeltas<std::uint32_t>(sink, env.offsets, env.indices);
    writeHalfPlanes(sink, env.values);
}

}  // namespace

void writeSidecar(const std::filesystem::path& path, const TranslucentAsset& a,
                  const SidecarWriteOptions& options) {
    validate(path, a);
    const ChunkProducer chunks[] = {
        {kHeader, ChunkCodec::Raw, true, [&](ChunkSink& s) { writeHeader(s, a); }},
        {kLayout, ChunkCodec::Raw, true, [&](ChunkSink& s) { writeLayout(s, a.layout); }},
        {kSamples, ChunkCodec::Zstd, true, [&](ChunkSink& s) { writeSamples(s, a.samples); }},
        {kVertexWeights, ChunkCodec::Zstd, true, [&](ChunkSink& s) { writeVertexWeights(s, a.vertexWeights); }},
        {kTransfer, ChunkCodec::Zstd, true, [&](ChunkSink& s) { writeTransfer(s, a.transfer, a.layout); }},
        {kEnvironment, ChunkCodec::Zstd, true,
         [&](ChunkSink& s) { writeEnvironment(s, a.environment, a.layout.cells()); }},
    };
    std::vector<ChunkProducer> all(std::begin(chunks), std::end(chunks));
    if (a.bake.identifier)  // optional: readers older than 2.1 skip it
        all.push_back({kBakeId, ChunkCodec::Raw, false, [&](ChunkSink& s) { s.writeU64(*a.bake.identifier); }});
    if (a.environment.fresnelBasis != FresnelBasis::Legendre)  // optional: readers older than 2.2 skip it
        all.push_back({kFresnelBasis, ChunkCodec::Raw, false,
                       [&](ChunkSink& s) { s.writeU32(std::uint32_t(a.environment.fresnelBasis)); }});
    if (a.transfer.selfTerm != SelfTerm::InTransfer)  // required: see sidecar.h
        all.push_back({kSelfTerm, ChunkCodec::Raw, true,
                       [&](ChunkSink& s) { s.writeU32(std::uint32_t(a.transfer.selfTerm)); }});
    if (a.environment.kind != EnvironmentVectorKind::Visible)  // required: see sidecar.h
        all.push_back({kEnvironmentKind, ChunkCodec::Raw, true,
                       [&](ChunkSink& s) { s.writeU32(std::uint32_t(a.environment.kind)); }});
    if (!a.transfer.harmonics.empty())  // optional: readers older than 2.5 (HARM) or 2.6 (HARP) skip it
        all.push_back({harmonicsChunk(a.transfer), ChunkCodec::Zstd, false,
                       [&](ChunkSink& s) { writeHarmonics(s, a.transfer, a.layout.cells()); }});
    writeChunkedFile(path, kSidecarKind, all, {options.zstdLevel});
}

}  // namespace opal
