#include "bake/bake_pipeline.h"

#include "bake/bake_identifier.h"
#include "bake/bake_report.h"
#include "bake/chart_parameterization.h"
#include "bake/mesh_import.h"
#include "bake/mesh_validation.h"
#include "bake/procedural_mesh.h"
#include "bake/random.h"
#include "bake/sample_count.h"
#include "bake/subdivision.h"
#include "bake/surface_sampler.h"
#include "bake/vertex_weights.h"
#include "schema/asset/asset_layer.h"
#include "schema/asset/asset_over_layer.h"
#include "schema/asset/cube_map.h"
#include "schema/asset/point_range.h"
#include "schema/asset/self_term.h"
#include "schema/scatter/profile_projection.h"
#include "schema/asset/sidecar.h"
#include "schema/asset/transfer_apply.h"
#include "schema/usd/crash_point.h"
#include "schema/usd/usda_writer.h"

#include <Imath/ImathBox.h>

#include <tbb/parallel_for.h>

#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace opal {

namespace {

// Times each stage for the report.
class StageClock {
public:
    explicit StageClock(BakeReport* report) : report_(report), start_(Clock::now()) {}
    void lap(std::string stage) {
        const auto now = Clock::now();
        if (report_) report_->seconds.emplace_back(std::move(stage), std::chrono::duration<double>(now - start_).count());
        start_ = now;
    }

private:
    using Clock = std::chrono::steady_clock;
    BakeReport* report_;
    Clock::time_point start_;
};

// A file's own scale (USDA metersPerUnit) is reported, never applied: --units-per-mm
// alone sets the units, whatever the input format.
void reportFileUnits(const BakeOptions& options, std::optional<double> metersPerUnit,
                     std::vector<std::string>* warnings) {
    if (!metersPerUnit) return;
    const double fileUnitsPerMm = 0.001 / *metersPerUnit;
    if (std::abs(fileUnitsPerMm - options.unitsPerMm) <= 1e-6 * options.unitsPerMm) return;
    std::ostringstream s;
    s << options.input << ": the layer's metersPerUnit " << *metersPerUnit << " means " << fileUnitsPerMm
      << " units per mm, but --units-per-mm is " << options.unitsPerMm << "; the bake uses --units-per-mm";
    warnings->push_back(s.str());
}

ImportedMesh loadControlMesh(const BakeOptions& options, std::vector<std::string>* warnings) {
    std::optional<ControlMesh> builtin = options.applyTo.empty() ? builtinMesh(options.input) : std::nullopt;
    if (builtin)
        return ImportedMesh{std::move(*builtin), {}, std::nullopt, std::nullopt};
    ImportedMesh imported =
        options.applyTo.empty() ? importMesh(options.input) : importMeshPrim(options.input, options.applyTo);
    checkPointRange(imported.mesh.positions, options.unitsPerMm, imported.mesh.source + " (at --units-per-mm)",
                    "vertex");
    warnings->insert(warnings->end(), imported.warnings.begin(), imported.warnings.end());
    reportFileUnits(options, imported.metersPerUnit, warnings);
    return imported;
}

// --scheme wins; "auto" takes the scheme the file authors, if any, else the mesh's own rule.
SubdivisionScheme chooseScheme(const BakeOptions& options, const ControlMesh& control,
                               std::optional<SubdivisionScheme> authored) {
    const SubdivisionScheme requested = parseSubdivisionScheme(options.scheme);
    if (requested != SubdivisionScheme::Automatic || !authored) return resolveSubdivisionScheme(control, requested);
    try {
        return resolveSubdivisionScheme(control, *authored);
    } catch (const Error& e) {
        throw Error(std::string(e.what()) + " (the file's subdivisionScheme asks for " +
                    std::string(subdivisionSchemeName(*authored)) + "; --scheme overrides it)");
    }
}

Imath::Box3f bounds(const RenderMesh& mesh) {
    Imath::Box3f box;
    for (const Imath::V3f& p : mesh.points) box.extendBy(p);
    return box;
}

Material defaultMaterial(const BakeOptions& options, const EditableRange& range, std::vector<std::string>* warnings) {
    const std::optional<Material> preset = findPreset(options.material);
    if (!preset) {
        std::string names;
        for (const NamedMaterial& m : jensenPresets()) names += (names.empty() ? "" : ", ") + std::string(m.name);
        throw Error("--material: unknown preset '" + options.material + "' (one of " + names + ")");
    }
    return range.clamp(*preset, warnings);
}

// The basis reaches across the whole object: r_max is the bounding-box diagonal in mm.
// Its errors name the asset and its size, since the mesh (or its units) is their cause.
ProfileBasis fitBasis(const BakeOptions& options, const std::string& assetName, const EditableRange& range,
                      const RenderMesh& mesh) {
    const Imath::Box3f box = bounds(mesh);
    const double diagonal = double((Imath::V3d(box.max) - Imath::V3d(box.min)).length()) / options.unitsPerMm;
    std::ostringstream where;
    where << "asset '" << assetName << "' (" << options.input << "): ";
    if (box.isEmpty() || !std::isfinite(diagonal) || !(diagonal > 0.0)) {
        where << "the mesh's bounding-box diagonal is " << (box.isEmpty() ? 0.0 : diagonal)
              << " mm, so the profile basis's radius range is empty";
        throw Error(where.str());
    }
    ProfileBasisSettings settings;
    settings.K = options.basisCount;
    settings.range = range;
    settings.rMax = diagonal;
    settings.seed = options.seed;
    try {
        return ProfileBasis::fit(settings);
    } catch (const Error& e) {
        where << "bounding-box diagonal " << diagonal << " mm at --units-per-mm " << options.unitsPerMm << ": "
              << e.what();
        throw Error(where.str());
    }
}

// The prim's own name for --apply-to: the over-layer's prim and the sidecar must agree.
std::string assetName(const BakeOptions& options) {
    const std::string& input = options.input;
    if (!options.applyTo.empty()) return options.applyTo.substr(options.applyTo.rfind('/') + 1);
    if (builtinMesh(input)) return input.substr(input.find(':') + 1);  // "builtin:wick" -> "wick"
    return assetNameFrom(std::filesystem::path(input).stem().string());
}

}  // namespace

TranslucentAsset prepareBake(const BakeOptions& options, ProgressSink* progress, const CancelToken& cancel,
                             BakeReport* report) {
    BakeReport local;
    BakeReport& r = report ? *report : local;
    StageClock clock(&r);
    if (!(options.unitsPerMm > 0.0) || !std::isfinite(options.unitsPerMm))
        throw Error("--units-per-mm must be a positive number");

    TranslucentAsset asset;
    asset.name = assetName(options);
    asset.unitsPerMm = options.unitsPerMm;
    asset.range = options.range.value_or(EditableRange::coveringPresets());
    asset.range.validate("editable range");
    asset.defaultMaterial = defaultMaterial(options, asset.range, &r.warnings);
    asset.layout = chartLayoutForSampleCount(options.samples);  // a bad count fails before any work
    try {  // the visibility stage comes last: refuse its settings before the long stages run
        (void)CubeMapLayout(options.visibility.cubeFaceSize);
    } catch (const Error& e) {
        throw Error(std::string("--env-res: ") + e.what());
    }
    if (options.visibility.terms == 0) throw Error("--env-terms must be at least 1");

    ImportedMesh imported = loadControlMesh(options, &r.warnings);
    ControlMesh& control = imported.mesh;
    const ValidationReport validation = validateAndRepair(control);
    r.warnings.insert(r.warnings.end(), validation.warnings.begin(), validation.warnings.end());
    clock.lap("import");
    cancel.throwIfRequested();

    SubdivisionOptions subdivision;
    subdivision.scheme = chooseScheme(options, control, imported.authoredScheme);
    subdivision.level = int(options.level ? *options.level
                                          : automaticSubdivisionLevel(control, subdivision.scheme, options.samples));
    {
        StageScope stage(progress, "subdivide", 1);
        asset.mesh = subdivide(control, subdivision);
    }
    clock.lap("subdivide");
    cancel.throwIfRequested();

    {
        StageScope stage(progress, "sample + parameterize", 3);
        SurfaceSampling sampling = sampleSurface(asset.mesh, options.samples, SamplingOptions{options.seed, 5});
        stage.advance(1);
        std::vector<Imath::V3f> positions;
        positions.reserve(sampling.samples.size());
        for (const SurfaceSample& s : sampling.samples) positions.push_back(s.position);
        reorderSamples(sampling, parameterizeCharts(positions, asset.layout));
        asset.samples = std::move(sampling.samples);
        stage.advance(1);
        asset.vertexWeights = computeVertexWeights(asset.mesh, asset.samples);
    }
    clock.lap("sample");
    cancel.throwIfRequested();

    {
        StageScope stage(progress, "fit profile basis", 1);
        asset.basis = fitBasis(options, asset.name, asset.range, asset.mesh);
    }
    clock.lap("basis");
    cancel.throwIfRequested();

    asset.bake.source = options.input;
    asset.bake.scheme = std::string(subdivisionSchemeName(subdivision.scheme));
    asset.bake.level = std::uint32_t(subdivision.level);
    asset.bake.seed = options.seed;
    asset.bake.envTerms = options.visibility.terms;
    asset.bake.envError = options.visibility.error;
    return asset;
}

void finishBake(const BakeOptions& options, TranslucentAsset& asset, ProgressSink* progress,
                const CancelToken& cancel, BakeReport* report) {
    BakeReport local;
    BakeReport& r = report ? *report : local;
    StageClock clock(&r);
    asset.environment = buildEnvironmentTransfer(asset.mesh, asset.samples, options.visibility, progress, cancel);
    clock.lap("visibility");

    {
        StageScope stage(progress, "measure transfer error", 1);
        roundToStoredPrecision(asset);  // what the sidecar keeps, so the report measures it
        r.transferRelRmse = measureTransferError(asset, options.seed);
    }
    clock.lap("measure");
    asset.bake.identifier = bakeIdentifier(options, asset);

    r.samples = asset.samples.size();
    r.charts = asset.layout.charts;
    r.grid = asset.layout.size();
    r.subdivisionLevel = asset.bake.level;
    r.renderVertices = asset.mesh.points.size();
    r.peakRssBytes = peakRssBytes();
}

TranslucentAsset bakeAsset(const BakeOptions& options, ProgressSink* progress, const CancelToken& cancel,
                           BakeReport* report) {
    BakeReport local;
    BakeReport& r = report ? *report : local;
    TranslucentAsset asset = prepareBake(options, progress, cancel, &r);
    const auto start = std::chrono::steady_clock::now();
    asset.transfer = buildTransfer(asset.samples, asset.layout, asset.unitsPerMm, asset.basis, options.transfer,
                                   progress, cancel, &r.transfer);
    r.seconds.emplace_back("transfer", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    finishBake(options, asset, progress, cancel, &r);
    return asset;
}

void writeBakedAsset(const StemLock& lock, const TranslucentAsset& asset, BakeReport* report,
                     const std::string& applyTo) {
    if (!asset.bake.identifier)
        throw Error(lock.stem().layer().string() + ": the asset has no bake identifier (bakeAsset gives it one)");
    const AssetStem& stem = lock.stem();
    const std::filesystem::path sidecar = stem.sidecar(*asset.bake.identifier);
    // The layer is formed (and the asset's name checked) before anything is written.
    const usda::Layer layer = applyTo.empty() ? assetToLayer(asset, sidecar.filename().string())
                                              : assetToOverLayer(asset, sidecar.filename().string(), applyTo);
    std::vector<std::string> local;
    std::vector<std::string>& warnings = report ? report->warnings : local;
    crashPoint("bake:writing");
    stem.removeStaleTemporaries(&warnings);
    crashPoint("bake:cleaned");
    writeSidecar(sidecar, asset);
    usda::writeUsdaFile(stem.layer(), layer);  // the commit
    crashPoint("bake:committed");
    stem.removeSidecarsExcept(*asset.bake.identifier, &warnings);
    crashPoint("bake:pruned");
    if (report) {
        report->sidecarFile = sidecar;
        report->sidecarBytes = std::filesystem::file_size(sidecar);
        report->peakRssBytes = peakRssBytes();
    }
}

void writeBakedAsset(const std::filesystem::path& stem, const TranslucentAsset& asset, BakeReport* report,
                     const std::string& applyTo) {
    const StemLock lock{AssetStem(stem)};
    writeBakedAsset(lock, asset, report, applyTo);
}

double measureTransferError(const TranslucentAsset& asset, std::uint64_t seed) {
    if (asset.transfer.selfTerm != SelfTerm::AtRunTime)
        throw Error("transfer error: asset '" + asset.name + "' holds its self term in the transfer (baked before "
                    "sidecar 2.3): re-bake it");
    const std::size_t n = asset.samples.size();
    Imath::Box3f box;
    for (const SurfaceSample& s : asset.samples) box.extendBy(s.position);
    const Imath::V3f light = box.center() + Imath::V3f(0.6f, 0.9f, 0.5f) * (box.max - box.min).length();
    std::vector<float> irradiance(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Imath::V3f d = light - asset.samples[i].position;
        irradiance[i] = std::max(0.0f, asset.samples[i].normal.dot(d.normalized())) / d.length2();
    }

    // Output samples to compare at: a seeded subset of at least 512 (all when fewer).
    std::vector<std::size_t> subset;
    const std::size_t wanted = std::min<std::size_t>(n, 512);
    Random random(seed, 0x7e57);
    for (std::size_t i = 0; i < n; ++i)
        if (random.uniformDouble() * double(n - i) < double(wanted - subset.size())) subset.push_back(i);

    const BasisLookup lookup(asset.basis);
    const std::array<std::vector<double>, 3> s =
        ProfileProjection(asset.basis, profileFitRadius(asset)).project(asset.defaultMaterial);
    std::array<std::vector<float>, 3> compressed;
    for (int c = 0; c < 3; ++c) compressed[c] = applyTransfer(asset.transfer, asset.layout, s[c], irradiance, asset.samples);

    // The self term R_disk(rho_o) E_o, which the relighter adds to the product of the
    // matrices (SelfTerm::AtRunTime), on both sides: the error is the compression's,
    // relative to all the light a sample returns.
    std::vector<float> self(3 * n);
    selfTermReflectance(asset.samples, asset.unitsPerMm, asset.defaultMaterial, self);
    for (int c = 0; c < 3; ++c)
        for (std::size_t i = 0; i < n; ++i) compressed[c][i] += self[3 * i + std::size_t(c)] * irradiance[i];

    // The exact sum_k s_k sum_{i != o} b_k(|x_o - x_i|) A_i E_i + R_disk E_o at each output.
    const int K = asset.basis.K();
    const double toMm = 1.0 / asset.unitsPerMm;
    std::vector<std::array<double, 3>> exact(subset.size());
    tbb::parallel_for(std::size_t(0), subset.size(), [&](std::size_t q) {
        const std::size_t o = subset[q];
        std::vector<float> b(static_cast<std::size_t>(K));
        std::array<double, 3> sum{0.0, 0.0, 0.0};
        for (std::size_t i = 0; i < n; ++i) {
            if (i == o) continue;
            lookup.evaluate(float((asset.samples[i].position - asset.samples[o].position).length() * toMm), b.data());
            const double weight = asset.samples[i].area * toMm * toMm * irradiance[i];
            for (int c = 0; c < 3; ++c) {
                double profile = 0.0;
                for (int k = 0; k < K; ++k) profile += s[c][std::size_t(k)] * b[std::size_t(k)];
                sum[c] += profile * weight;
            }
        }
        for (int c = 0; c < 3; ++c) sum[c] += double(self[3 * o + std::size_t(c)]) * irradiance[o];
        exact[q] = sum;
    });
    double errorSq = 0.0, exactSq = 0.0;
    for (std::size_t q = 0; q < subset.size(); ++q)
        for (int c = 0; c < 3; ++c) {
            const double d = compressed[c][subset[q]] - exact[q][c];
            errorSq += d * d;
            exactSq += exact[q][c] * exact[q][c];
        }
    return exactSq > 0.0 ? std::sqrt(errorSq / exactSq) : 0.0;
}

}  // namespace opal
