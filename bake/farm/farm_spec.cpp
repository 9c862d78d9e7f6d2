#include "bake/farm/farm_spec.h"

#include "bake/farm/task_file.h"
#include "schema/error.h"

namespace opal {

namespace {

void writeRange(SectionWriter& w, const EditableRange& r) {
    for (double v : {r.sigmaSPrimeMin, r.sigmaSPrimeMax, r.sigmaAMin, r.sigmaAMax, r.etaMin, r.etaMax}) w.f64(v);
}

EditableRange readRange(SectionReader& r) {
    EditableRange e;
    for (double* v : {&e.sigmaSPrimeMin, &e.sigmaSPrimeMax, &e.sigmaAMin, &e.sigmaAMax, &e.etaMin, &e.etaMax})
        *v = r.f64("editable range");
    return e;
}

void writeOptions(SectionWriter& w, const BakeOptions& o) {
    w.text(o.input);
    w.text(o.scheme);
    w.u32(o.level ? 1 : 0);
    w.u32(o.level.value_or(0));
    w.u64(o.samples);
    w.f64(o.unitsPerMm);
    w.u32(o.range ? 1 : 0);
    writeRange(w, o.range.value_or(EditableRange{}));
    w.text(o.material);
    w.u32(std::uint32_t(o.basisCount));
    w.f64(o.transfer.keepFraction);
    w.f64(o.transfer.energyFraction);
    w.u32(o.transfer.minPerRow);
    w.u32(o.visibility.cubeFaceSize);
    w.u32(o.visibility.terms);
    w.f64(o.visibility.error);
    w.u32(o.visibility.fresnelTerms);
    w.u32(std::uint32_t(o.visibility.fresnelBasis));
    w.u64(o.seed);
}

BakeOptions readOptions(SectionReader& r) {
    BakeOptions o;
    o.input = r.text("input");
    o.scheme = r.text("scheme");
    const bool hasLevel = r.u32("level given") != 0;
    const std::uint32_t level = r.u32("level");
    if (hasLevel) o.level = level;
    o.samples = r.u64("samples");
    o.unitsPerMm = r.f64("units per mm");
    const bool hasRange = r.u32("range given") != 0;
    const EditableRange range = readRange(r);
    if (hasRange) o.range = range;
    o.material = r.text("material");
    o.basisCount = int(r.u32("basis count"));
    o.transfer.keepFraction = r.f64("keep fraction");
    o.transfer.energyFraction = r.f64("energy fraction");
    o.transfer.minPerRow = r.u32("keep minimum");
    o.visibility.cubeFaceSize = r.u32("cube face size");
    o.visibility.terms = r.u32("environment terms");
    o.visibility.error = r.f64("environment error");
    o.visibility.fresnelTerms = r.u32("Fresnel terms");
    const std::uint32_t basis = r.u32("Fresnel basis");
    if (basis > std::uint32_t(FresnelBasis::Schlick)) r.fail("Fresnel basis", "is " + std::to_string(basis));
    o.visibility.fresnelBasis = FresnelBasis(basis);
    o.seed = r.u64("seed");
    return o;
}

void writeMaterial(SectionWriter& w, const Material& m) {
    for (int c = 0; c < 3; ++c) w.f64(m.sigmaSPrime[c]);
    for (int c = 0; c < 3; ++c) w.f64(m.sigmaA[c]);
    w.f64(m.eta);
}

Material readMaterial(SectionReader& r) {
    Material m;
    for (int c = 0; c < 3; ++c) m.sigmaSPrime[c] = r.f64("default material");
    for (int c = 0; c < 3; ++c) m.sigmaA[c] = r.f64("default material");
    m.eta = r.f64("default material");
    return m;
}

template <class T>
std::vector<T> copyOf(std::span<const T> values) {
    return std::vector<T>(values.begin(), values.end());
}

void writeAsset(SectionWriter& w, const TranslucentAsset& a) {
    w.text(a.name);
    w.f64(a.unitsPerMm);
    w.array(a.mesh.points);
    w.array(a.mesh.normals);
    w.array(a.mesh.faceVertexCounts);
    w.array(a.mesh.faceVertexIndices);
    w.u32(a.layout.charts);
    w.u32(a.layout.log2Size);
    w.array(a.samples);
    w.array(a.vertexWeights.offsets);
    w.array(a.vertexWeights.samples);
    w.array(a.vertexWeights.weights);
    w.array(copyOf(a.basis.radii()));
    w.array(copyOf(a.basis.weights()));
    w.array(copyOf(a.basis.values()));
    w.array(copyOf(a.basis.eigenvalues()));
    writeRange(w, a.basis.range());
    writeMaterial(w, a.defaultMaterial);
    writeRange(w, a.range);
    w.text(a.bake.source);
    w.text(a.bake.scheme);
    w.u32(a.bake.level);
    w.u64(a.bake.seed);
    w.u32(a.bake.envTerms);
    w.f64(a.bake.envError);
}

TranslucentAsset readAsset(SectionReader& r) {
    TranslucentAsset a;
    a.name = r.text("asset name");
    a.unitsPerMm = r.f64("units per mm");
    a.mesh.points = r.array<Imath::V3f>("mesh points");
    a.mesh.normals = r.array<Imath::V3f>("mesh normals");
    a.mesh.faceVertexCounts = r.array<std::int32_t>("face vertex counts");
    a.mesh.faceVertexIndices = r.array<std::int32_t>("face vertex indices");
    a.layout.charts = r.u32("charts");
    a.layout.log2Size = r.u32("chart size");
    if (a.layout.log2Size > 15 || a.layout.charts > (1u << 20)) r.fail("chart layout", "is out of range");
    a.samples = r.array<SurfaceSample>("samples");
    if (a.samples.size() != a.layout.cells())
        r.fail("samples", "number " + std::to_string(a.samples.size()) + ", the layout has " +
                              std::to_string(a.layout.cells()) + " cells");
    a.vertexWeights.offsets = r.array<std::uint32_t>("vertex weight offsets");
    a.vertexWeights.samples = r.array<std::uint32_t>("vertex weight samples");
    a.vertexWeights.weights = r.array<float>("vertex weights");
    std::vector<double> radii = r.array<double>("basis radii");
    std::vector<double> weights = r.array<double>("basis weights");
    std::vector<double> values = r.array<double>("basis values");
    std::vector<double> eigenvalues = r.array<double>("basis eigenvalues");
    const EditableRange basisRange = readRange(r);
    try {
        a.basis = ProfileBasis(std::move(radii), std::move(weights), std::move(values), std::move(eigenvalues),
                               basisRange);
    } catch (const Error& e) {
        r.fail("profile basis", std::string("is inconsistent: ") + e.what());
    }
    a.defaultMaterial = readMaterial(r);
    a.range = readRange(r);
    a.bake.source = r.text("bake source");
    a.bake.scheme = r.text("bake scheme");
    a.bake.level = r.u32("bake level");
    a.bake.seed = r.u64("bake seed");
    a.bake.envTerms = r.u32("environment terms");
    a.bake.envError = r.f64("environment error");
    return a;
}

}  // namespace

std::string encodeFarmSpec(const FarmSpec& spec) {
    SectionWriter w;
    writeOptions(w, spec.options);
    w.text(spec.stem);
    w.text(spec.workingDirectory);
    w.u32(spec.shards);
    return w.take();
}

void writeFarmSpec(const FarmFolder& folder, const FarmSpec& spec) {
    const std::string section = encodeFarmSpec(spec);
    writeTaskFile(folder.spec(), std::span(&section, 1));
}

FarmSpec readFarmSpec(const FarmFolder& folder) {
    SectionReader r = TaskFile(folder.spec()).section(0);
    FarmSpec spec;
    spec.options = readOptions(r);
    spec.stem = r.text("stem");
    spec.workingDirectory = r.text("working directory");
    spec.shards = r.u32("shards");
    if (spec.shards == 0) r.fail("shards", "is 0");
    r.expectEnd();
    return spec;
}

void writePreparedBake(const FarmFolder& folder, const PreparedBake& prepared) {
    SectionWriter w;
    writeAsset(w, prepared.asset);
    w.u64(prepared.warnings.size());
    for (const std::string& warning : prepared.warnings) w.text(warning);
    const std::string section = w.take();
    writeTaskFile(folder.output(FarmStage::Prepare, 0), std::span(&section, 1));
}

PreparedBake readPreparedBake(const FarmFolder& folder) {
    SectionReader r = TaskFile(folder.output(FarmStage::Prepare, 0)).section(0);
    PreparedBake prepared;
    prepared.asset = readAsset(r);
    const std::uint64_t warnings = r.u64("warning count");
    for (std::uint64_t i = 0; i < warnings; ++i) prepared.warnings.push_back(r.text("warning"));
    r.expectEnd();
    return prepared;
}

}  // namespace opal
