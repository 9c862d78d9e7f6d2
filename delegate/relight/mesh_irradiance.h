// The irradiance moments of one placed translucent mesh, kept per light so that an edit recomputes
// only what changed (docs/ARCHITECTURE.md#irradiance): moving or editing a light recomputes that
// light's E_m alone and re-sums; moving the mesh recomputes every light (they all depend on where
// the samples are); moving an occluder re-shadows the analytic and shadow-field lights only.
//
// The moment count is the asset's environment transfer's fresnelTerms (the baked dome
// vectors fix it), or 2 when the asset has no environment transfer.
#pragma once

#include "delegate/relight/analytic_light.h"
#include "delegate/relight/environment_light.h"
#include "delegate/relight/environment_reference.h"
#include "delegate/relight/environment_vectors.h"
#include "delegate/relight/fresnel_response.h"
#include "delegate/hd/types.h"
#include "delegate/relight/irradiance.h"
#include "delegate/relight/shadow_field_light.h"

#include <map>
#include <memory>
#include <variant>

namespace opal {

class RayScene;

class MeshIrradiance {
public:
    // Shadow rays start this fraction of the ray scene's extent along the normal (as the
    // bake's environment visibility does), clear of the surface the sample lies on.
    static constexpr float kShadowOffset = 1e-4f;

    MeshIrradiance(std::shared_ptr<const TranslucentAsset> asset, const Imath::M44d& objectToWorld);

    std::uint32_t terms() const { return terms_; }
    const PlacedSamples& samples() const { return placed_; }

    // Re-places the samples and recomputes every light (shadows from `scene`).
    void setTransform(const Imath::M44d& objectToWorld, const RayScene& scene);
    // Adds or replaces one light and recomputes only its contribution.
    void setLight(const hd::SdfPath& id, const AnalyticLight& light, const RayScene& scene);
    void setLight(const hd::SdfPath& id, std::shared_ptr<const EnvironmentLight> light);
    void setLight(const hd::SdfPath& id, std::shared_ptr<const ShadowFieldLight> light, const RayScene& scene);
    void removeLight(const hd::SdfPath& id);
    // Occluders changed: recompute the shadowed (analytic and shadow-field) lights.
    void updateShadows(const RayScene& scene);

    // sum over lights of E_m(x_i): what RelightEngine::setIrradiance takes.
    const IrradianceMoments& moments() const { return total_; }
    // E(x_i; eta) with the exact F_t(eta, .) for analytic and shadow-field lights (at each
    // sample's arrival cosine) and sum_m c_m(eta) E_m for
    // domes (the engine's baked vectors, F_t in moment form): samples x 3, the engine's own
    // E but for the analytic lights' Fresnel fit.
    std::vector<float> exactIrradiance(double eta) const;
    // The true E(x_i; eta), the reference mode's input to the reference gather: analytic
    // lights as exactIrradiance, domes by the brute-force hemisphere integral of
    // environment_reference.h instead of the baked vectors. Each dome's E is kept until the
    // dome, the transform or eta changes; the asset's visibility is traced at the first
    // call with a dome and kept (so an eta edit or a dome rotation traces no rays).
    std::vector<float> referenceIrradiance(double eta);
    // The parts of the last light's recomputation (wall ms): its arrivals (E and the
    // arrival cosine per sample; domes: none), its moments (domes: the map on the cube and
    // EnvironmentVectors::addDome, not the vectors' build with the first dome), and the
    // re-sum of every light's term (setLight and removeLight; the others re-sum after
    // several lights).
    struct UpdateTimes {
        double arrivalsMs = 0.0, momentsMs = 0.0, resumMs = 0.0;
    };
    const UpdateTimes& lastUpdate() const { return lastUpdate_; }
    // Bytes held: the placed samples, each light's moments and arrivals, the dome vectors.
    std::size_t memoryBytes() const;

private:
    using Source = std::variant<AnalyticLight, std::shared_ptr<const EnvironmentLight>,
                                std::shared_ptr<const ShadowFieldLight>>;
    struct Contribution {
        Source source;
        IrradianceMoments moments;
        std::vector<LightArrival> arrivals;  // analytic and shadow-field lights: for exactIrradiance
        std::vector<float> referenceE;       // domes: the last referenceIrradiance, at referenceEta
        double referenceEta = 0.0;
    };
    void compute(Contribution& contribution, const RayScene* scene);
    void resum();
    std::vector<float> arrivalIrradiance(double eta) const;
    static bool isDome(const Contribution& c) {
        return std::holds_alternative<std::shared_ptr<const EnvironmentLight>>(c.source);
    }

    std::shared_ptr<const TranslucentAsset> asset_;
    Imath::M44d objectToWorld_;
    std::uint32_t terms_ = 0;
    // The asset's dome vectors' basis; analytic lights use it too so that every light sums
    // into the same moments (Legendre without a dome transfer).
    FresnelBasis basis_ = FresnelBasis::Legendre;
    FresnelResponse response_;
    PlacedSamples placed_;
    std::unique_ptr<EnvironmentVectors> environment_;        // built with the first dome
    // The last dome map's unoccluded integral U, in the dome's frame and before the dome's
    // colour and intensity: kept while only transforms and colour change (a rotation, an
    // intensity slider), rebuilt for another map. It is summed over a cube of at least
    // kOpenFaceSize texels a side, finer than the bake's 32: at 32 the texels that straddle
    // a normal's horizon put 3.1% of error into the dome's E at the 95th percentile of the
    // 16,384-sample bunny's samples (against the reference of docs/ARCHITECTURE.md#dome-reference),
    // 2.4% at 64 and at 128 (`opal-bench error-sources --material short`, 2026-11-28). The
    // sums take 73 ms at 64 against 18.5 ms at 32, once per map.
    static constexpr std::uint32_t kOpenFaceSize = 64;
    struct OpenDome {
        std::shared_ptr<const LatLongMap> map;  // held: a freed map's address may come back
        std::unique_ptr<const DomeConvolution> integral;
    };
    OpenDome open_;
    std::unique_ptr<const EnvironmentReference> reference_;   // built with the first referenceIrradiance
    std::map<hd::SdfPath, Contribution> lights_;
    IrradianceMoments total_;
    UpdateTimes lastUpdate_;
};

}  // namespace opal
