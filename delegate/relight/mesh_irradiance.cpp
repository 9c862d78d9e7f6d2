#include "delegate/relight/mesh_irradiance.h"

#include "delegate/relight/stopwatch.h"
#include "raytrace/ray_scene.h"
#include "schema/error.h"
#include "schema/scatter/fresnel_moments.h"

#include <algorithm>
#include <string>

namespace opal {

namespace {

constexpr std::uint32_t kTermsWithoutEnvironment = 2;

std::uint32_t momentTerms(const TranslucentAsset& asset) {
    if (asset.environment.offsets.empty()) return kTermsWithoutEnvironment;
    const std::uint32_t terms = asset.environment.fresnelTerms;
    if (terms < 1 || terms > std::uint32_t(kMaxFresnelTerms))
        throw Error("irradiance: asset '" + asset.name + "' has " + std::to_string(terms) +
                    " Fresnel terms in its environment transfer");
    return terms;
}

const TranslucentAsset& require(const std::shared_ptr<const TranslucentAsset>& asset) {
    if (!asset) throw Error("irradiance: no asset");
    return *asset;
}

}  // namespace

MeshIrradiance::MeshIrradiance(std::shared_ptr<const TranslucentAsset> asset, const Imath::M44d& objectToWorld)
    : asset_(std::move(asset)),
      objectToWorld_(objectToWorld),
      terms_(momentTerms(require(asset_))),
      basis_(asset_->environment.offsets.empty() ? FresnelBasis::Legendre : asset_->environment.fresnelBasis),
      response_(asset_->range.etaMin, asset_->range.etaMax, int(terms_), basis_),
      placed_(placeSamples(asset_->samples, objectToWorld)),
      total_(std::uint32_t(asset_->samples.size()), terms_) {}

void MeshIrradiance::compute(Contribution& c, const RayScene* scene) {
    c.moments = IrradianceMoments(std::uint32_t(placed_.positions.size()), terms_, basis_);
    c.referenceE.clear();
    const float offset = scene ? kShadowOffset * scene->extent() : 0.0f;
    lastUpdate_ = {};
    const Stopwatch arrivals;
    if (const auto* light = std::get_if<AnalyticLight>(&c.source)) c.arrivals = lightArrivals(*light, placed_, scene, offset);
    if (const auto* field = std::get_if<std::shared_ptr<const ShadowFieldLight>>(&c.source))
        c.arrivals = (*field)->arrivals(placed_, scene, offset);
    if (!isDome(c)) {
        lastUpdate_.arrivalsMs = arrivals.ms();
        const Stopwatch moments;
        addMoments(c.arrivals, response_, c.moments);
        lastUpdate_.momentsMs = moments.ms();
        return;
    }
    const auto& dome = std::get<std::shared_ptr<const EnvironmentLight>>(c.source);
    if (asset_->environment.offsets.empty())
        throw Error("irradiance: asset '" + asset_->name + "' has no environment transfer for a dome light");
    if (!environment_) environment_ = std::make_unique<EnvironmentVectors>(asset_->environment, asset_->samples.size());
    const Stopwatch moments;
    const CubeMapLayout cube(asset_->environment.cubeFaceSize);
    const DomeConvolution* open = nullptr;
    if (environment_->kind() == EnvironmentVectorKind::Occluded) {
        if (!open_.integral || open_.map != dome->map()) {
            open_.integral.reset();  // a failed build leaves no stale integral
            const CubeMapLayout fine(std::max(kOpenFaceSize, cube.faceSize()));
            open_.integral = std::make_unique<const DomeConvolution>(fine, dome->domeCubeMap(fine), terms_, basis_);
            open_.map = dome->map();
        }
        open = open_.integral.get();
    }
    const Rgb& scale = dome->scale();
    environment_->addDome(dome->cubeRadiance(cube, objectToWorld_), open,
                          Imath::V3f(float(scale.x), float(scale.y), float(scale.z)),
                          dome->domeFromObject(objectToWorld_), asset_->samples, c.moments);
    lastUpdate_.momentsMs = moments.ms();
}

void MeshIrradiance::resum() {
    const Stopwatch clock;
    total_ = IrradianceMoments(std::uint32_t(placed_.positions.size()), terms_, basis_);
    for (const auto& [id, c] : lights_) total_ += c.moments;
    lastUpdate_.resumMs = clock.ms();
}

void MeshIrradiance::setTransform(const Imath::M44d& objectToWorld, const RayScene& scene) {
    placed_ = placeSamples(asset_->samples, objectToWorld);
    objectToWorld_ = objectToWorld;
    for (auto& [id, c] : lights_) compute(c, &scene);
    resum();
}

void MeshIrradiance::setLight(const hd::SdfPath& id, const AnalyticLight& light, const RayScene& scene) {
    Contribution c{light, {}, {}, {}, 0.0};
    compute(c, &scene);
    lights_.insert_or_assign(id, std::move(c));
    resum();
}

void MeshIrradiance::setLight(const hd::SdfPath& id, std::shared_ptr<const EnvironmentLight> light) {
    if (!light) throw Error("irradiance: dome light " + id + " has no map");
    Contribution c{std::move(light), {}, {}, {}, 0.0};
    compute(c, nullptr);
    lights_.insert_or_assign(id, std::move(c));
    resum();
}

void MeshIrradiance::setLight(const hd::SdfPath& id, std::shared_ptr<const ShadowFieldLight> light,
                              const RayScene& scene) {
    if (!light) throw Error("irradiance: shadow-field light " + id + " has no field");
    Contribution c{std::move(light), {}, {}, {}, 0.0};
    compute(c, &scene);
    lights_.insert_or_assign(id, std::move(c));
    resum();
}

void MeshIrradiance::removeLight(const hd::SdfPath& id) {
    if (lights_.erase(id)) resum();
}

void MeshIrradiance::updateShadows(const RayScene& scene) {
    for (auto& [id, c] : lights_)
        if (!isDome(c)) compute(c, &scene);
    resum();
}

std::vector<float> MeshIrradiance::arrivalIrradiance(double eta) const {
    std::vector<float> rgb(placed_.positions.size() * 3, 0.0f);
    for (const auto& [id, contribution] : lights_)
        if (!isDome(contribution)) addExactIrradiance(contribution.arrivals, eta, rgb);
    return rgb;
}

std::vector<float> MeshIrradiance::exactIrradiance(double eta) const {
    std::vector<float> rgb = arrivalIrradiance(eta);
    const std::vector<double> c = fresnelMoments(eta, int(terms_), basis_);
    for (const auto& [id, contribution] : lights_) {
        if (!isDome(contribution)) continue;
        const std::vector<float> dome = contribution.moments.combine(c);
        for (std::size_t j = 0; j < rgb.size(); ++j) rgb[j] += dome[j];
    }
    return rgb;
}

std::vector<float> MeshIrradiance::referenceIrradiance(double eta) {
    std::vector<float> rgb = arrivalIrradiance(eta);
    for (auto& [id, contribution] : lights_) {
        const auto* dome = std::get_if<std::shared_ptr<const EnvironmentLight>>(&contribution.source);
        if (!dome) continue;
        if (contribution.referenceE.empty() || contribution.referenceEta != eta) {
            if (!reference_)
                reference_ = std::make_unique<const EnvironmentReference>(asset_, EnvironmentReference::faceSizeFor(*asset_));
            contribution.referenceE = reference_->irradiance(**dome, objectToWorld_, eta);
            contribution.referenceEta = eta;
        }
        for (std::size_t j = 0; j < rgb.size(); ++j) rgb[j] += contribution.referenceE[j];
    }
    return rgb;
}

std::size_t MeshIrradiance::memoryBytes() const {
    const auto moments = [](const IrradianceMoments& m) { return m.values.capacity() * sizeof(float); };
    std::size_t bytes = (placed_.positions.capacity() + placed_.normals.capacity()) * sizeof(Imath::V3f) + moments(total_);
    if (environment_) bytes += environment_->memoryBytes();
    if (open_.integral) bytes += open_.integral->memoryBytes();
    if (reference_) bytes += reference_->memoryBytes();
    for (const auto& [path, contribution] : lights_)
        bytes += moments(contribution.moments) + contribution.arrivals.capacity() * sizeof(LightArrival) +
                 contribution.referenceE.capacity() * sizeof(float);
    return bytes;
}

}  // namespace opal
