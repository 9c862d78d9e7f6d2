// readSidecar: decode each chunk into a local payload, validating as it goes (sizes before
// allocations, CSR offsets before the indices that depend on them), then hand it over.
#include "schema/asset/array_codec.h"
#include "schema/asset/chunked_file.h"
#include "schema/asset/normal_harmonics.h"
#include "schema/asset/point_range.h"
#include "schema/asset/sidecar.h"
#include "schema/asset/sidecar_checks.h"
#include "schema/asset/transfer_value_grid.h"
#include "schema/error.h"

#include <initializer_list>
#include <string>
#include <string_view>

namespace opal {
namespace {

using namespace sidecar_chunk;

constexpr ChunkTag kKnownChunks[] = {kHeader, kLayout, kSamples, kVertexWeights, kTransfer, kEnvironment, kBakeId,
                                     kFresnelBasis, kSelfTerm, kEnvironmentKind, kHarmonics, kPositionHarmonics};

struct Payload {
    ChartLayout layout;
    std::vector<SurfaceSample> samples;
    VertexWeights vertexWeights;
    CompressedTransfer transfer;
    EnvironmentTransfer environment;
};

std::string str(std::uint64_t v) { return std::to_string(v); }

SidecarHeader readHeader(ChunkSource src) {
    SidecarHeader h;
    h.name = src.readString(sidecar::kMaxNameBytes, "asset name");
    h.unitsPerMm = src.readF64();
    h.sampleCount = src.readU64();
    h.basisCount = src.readU32();
    h.vertexCount = src.readU32();
    h.meshTopologyHash = src.readU64();
    src.finish();
    sidecar::checkUnitsPerMm(h.unitsPerMm, src.context());
    return h;
}

std::uint64_t readBakeId(ChunkSource src) {
    const std::uint64_t id = src.readU64();
    src.finish();
    return id;
}

ChartLayout readLayout(ChunkSource src, const SidecarHeader& header) {
    ChartLayout layout;
    layout.charts = src.readU32();
    layout.log2Size = src.readU32();
    src.finish();
    sidecar::checkLayout(layout, src.context());
    if (layout.cells() != header.sampleCount)
        src.fail("layout has " + str(layout.cells()) + " cells, the header says " + str(header.sampleCount) + " samples");
    return layout;
}

std::vector<SurfaceSample> readSamples(ChunkSource src, std::uint64_t expected, double unitsPerMm) {
    std::uint64_t count = src.readU64();
    if (count != expected) src.fail(str(count) + " samples, the chart layout has " + str(expected) + " cells");
    std::vector<float> positions = readFloatPlanes(src, 3 * count, "positions");
    std::vector<float> normals = readFloatPlanes(src, 3 * count, "normals");
    std::vector<float> areas = readFloatPlanes(src, count, "areas");
    src.finish();
    std::vector<SurfaceSample> samples(count);
    for (std::size_t i = 0; i < count; ++i) {
        samples[i].position = {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
        samples[i].normal = {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]};
        samples[i].area = areas[i];
    }
    sidecar::checkSamples(samples, expected, src.context());
    std::vector<Imath::V3f> points(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) points[i] = samples[i].position;
    checkPointRange(points, unitsPerMm, src.context(), "sample");
    return samples;
}

VertexWeights readVertexWeights(ChunkSource src, std::uint64_t samples, std::uint32_t expectedVertices) {
    std::uint32_t vertices = src.readU32();
    if (vertices != expectedVertices)
        src.fail(str(vertices) + " vertices, the header says " + str(expectedVertices));
    std::uint64_t entries = src.readU64();
    VertexWeights w;
    w.offsets = src.readArray<std::uint32_t>(std::uint64_t(vertices) + 1, "vertex offsets");
    sidecar::checkOffsets<std::uint32_t>(w.offsets, vertices, entries, src.context(), "vertex offsets");
    w.samples = readRowDeltas<std::uint32_t>(src, w.offsets, "vertex samples");
    w.weights = readFloatPlanes(src, entries, "weights");
    src.finish();
    sidecar::checkVertexWeights(w, samples, src.context());
    return w;
}

// Values on the grid of `step` (transfer_value_grid.h), or float32 for step 0.
std::vector<float> readMatrixValues(ChunkSource& src, const SparseMatrix& m, double step,
                                    const TransferValueGrid& grid, const std::string& what) {
    if (step == 0.0) return readFloatPlanes(src, m.columns.size(), what);
    return grid.values(m, readVarints(src, m.columns.size(), what), step);
}

SparseMatrix readMatrix(ChunkSource& src, std::uint64_t samples, std::size_t k, const TransferValueGrid& grid,
                        double& step) {
    std::string what = "matrix " + str(k);
    SparseMatrix m;
    m.rows = src.readU32();
    m.cols = src.readU32();
    std::uint64_t entries = src.readU64();
    sidecar::checkMatrixShape(m, samples, src.context(), what);
    m.rowOffsets = src.readArray<std::uint64_t>(std::uint64_t(m.rows) + 1, what + " row offsets");
    sidecar::checkOffsets<std::uint64_t>(m.rowOffsets, m.rows, entries, src.context(), what + " row offsets");
    m.columns = readRowDeltas<std::uint64_t>(src, m.rowOffsets, what + " columns");
    sidecar::checkIndices<std::uint64_t>(m.rowOffsets, m.columns, m.cols, true, src.context(), what + " columns");
    step = src.readF64();
    sidecar::checkValueStep(step, src.context(), what);
    m.values = readMatrixValues(src, m, step, grid, what + " values");
    sidecar::checkFinite(m.values, src.context(), what + " values");
    return m;
}

CompressedTransfer readTransfer(ChunkSource src, const ChartLayout& layout, std::uint32_t expectedK) {
    const std::uint64_t samples = layout.cells();
    const TransferValueGrid grid(layout);
    std::uint32_t K = src.readU32();
    CompressedTransfer t;
    t.keepFraction = src.readF64();
    t.energyFraction = src.readF64();
    sidecar::checkTransferHeader(K, t.keepFraction, t.energyFraction, src.context());
    if (K != expectedK) src.fail("K = " + str(K) + " matrices, the header says " + str(expectedK));
    t.valueSteps.resize(K);
    for (std::size_t k = 0; k < K; ++k) t.perBasis.push_back(readMatrix(src, samples, k, grid, t.valueSteps[k]));
    src.finish();
    return t;
}

EnvironmentTransfer readEnvironment(ChunkSource src, std::uint64_t samples) {
    EnvironmentTransfer env;
    env.cubeFaceSize = src.readU32();
    env.fresnelTerms = src.readU32();
    sidecar::checkEnvironmentHeader(env, src.context());
    std::uint64_t rows = src.readU64(), entries = src.readU64();
    if (rows != 0 && rows != samples * env.fresnelTerms)
        src.fail(str(rows) + " rows, expected 0 (not baked) or samples x Fresnel terms = " +
                 str(samples * env.fresnelTerms));
    if (rows == 0 && entries != 0) src.fail(str(entries) + " entries without rows");
    if (rows != 0) env.offsets = src.readArray<std::uint32_t>(rows + 1, "row offsets");
    if (rows != 0) sidecar::checkOffsets<std::uint32_t>(env.offsets, rows, entries, src.context(), "row offsets");
    env.indices = readRowDeltas<std::uint32_t>(src, env.offsets, "cube-map indices");
    env.values = readHalfPlanes(src, entries, "values");
    src.finish();
    sidecar::checkEnvironment(env, samples, src.context());
    return env;
}

// HARM (9 functions) or HARP (36 with their frame) into transfer.harmonics and harmonicSet.
void readHarmonics(ChunkSource src, std::uint64_t samples, std::uint32_t K, std::uint32_t expectedCount,
                   CompressedTransfer& transfer) {
    const std::uint32_t terms = src.readU32(), basisCount = src.readU32();
    const std::uint64_t rows = src.readU64();
    if (terms != expectedCount || basisCount != K || rows != samples)
        src.fail(str(rows) + " samples x K = " + str(basisCount) + " x " + str(terms) + " harmonics, expected " +
                 str(samples) + " x " + str(K) + " x " + str(expectedCount));
    HarmonicSet set;
    set.count = terms;
    if (terms != kNormalHarmonics) {
        for (int a = 0; a < 3; ++a) set.centre[a] = float(src.readF64());
        set.inverseScale = float(src.readF64());
    }
    std::vector<float> values = readFloatPlanes(src, samples * K * terms, "values");
    src.finish();
    transfer.harmonicSet = set;
    transfer.harmonics = std::move(values);
    sidecar::checkHarmonics(transfer, samples, src.context());
}

// A u32 chunk holding one of `names` (value v is names[v]); anything else is refused
// naming the choices.
std::uint32_t readChoice(ChunkSource src, std::string_view what, std::initializer_list<std::string_view> names) {
    const std::uint32_t value = src.readU32();
    if (value >= names.size()) {
        std::string choices;
        for (std::uint32_t v = 0; v < names.size(); ++v)
            choices += (v ? ", " : "") + str(v) + " " + std::string(names.begin()[v]);
        src.fail("unknown " + std::string(what) + " " + str(value) + " (" + choices + ")");
    }
    src.finish();
    return value;
}

FresnelBasis readFresnelBasis(ChunkSource src) {
    return FresnelBasis(readChoice(std::move(src), "Fresnel basis", {"Legendre", "Schlick"}));
}

SelfTerm readSelfTerm(ChunkSource src) {
    return SelfTerm(readChoice(std::move(src), "self-term placement", {"in the transfer", "at run time"}));
}

EnvironmentVectorKind readEnvironmentKind(ChunkSource src) {
    return EnvironmentVectorKind(
        readChoice(std::move(src), "environment vector kind", {"visible transport", "occluded residual"}));
}

}  // namespace

SidecarHeader readSidecar(const std::filesystem::path& path, TranslucentAsset& asset) {
    ChunkedFileReader file(path, kSidecarKind);
    file.rejectUnknownRequired(kKnownChunks);
    SidecarHeader header = readHeader(file.open(kHeader));
    if (file.find(kBakeId)) header.bakeId = readBakeId(file.open(kBakeId));
    Payload p;
    p.layout = readLayout(file.open(kLayout), header);
    std::uint64_t samples = p.layout.cells();
    p.samples = readSamples(file.open(kSamples), samples, header.unitsPerMm);
    p.vertexWeights = readVertexWeights(file.open(kVertexWeights), samples, header.vertexCount);
    p.transfer = readTransfer(file.open(kTransfer), p.layout, header.basisCount);
    p.environment = readEnvironment(file.open(kEnvironment), samples);
    if (file.find(kFresnelBasis)) p.environment.fresnelBasis = readFresnelBasis(file.open(kFresnelBasis));
    if (file.find(kSelfTerm)) p.transfer.selfTerm = readSelfTerm(file.open(kSelfTerm));
    if (file.find(kEnvironmentKind)) p.environment.kind = readEnvironmentKind(file.open(kEnvironmentKind));
    if (file.find(kHarmonics) && file.find(kPositionHarmonics))
        throw Error(path.string() + ": holds both harmonic transfers (chunks 'HARM' and 'HARP'); write the file again");
    if (file.find(kHarmonics))
        readHarmonics(file.open(kHarmonics), samples, header.basisCount, kNormalHarmonics, p.transfer);
    if (file.find(kPositionHarmonics))
        readHarmonics(file.open(kPositionHarmonics), samples, header.basisCount, kMaxHarmonics, p.transfer);
    asset.layout = p.layout;
    asset.samples = std::move(p.samples);
    asset.vertexWeights = std::move(p.vertexWeights);
    asset.transfer = std::move(p.transfer);
    asset.environment = std::move(p.environment);
    return header;
}

}  // namespace opal
