// Relighting one translucent asset: the paper's rendering algorithm, steps 1-5
// (docs/ARCHITECTURE.md#relighting), with Fresnel moments (#fresnel-moments).
//
//   setIrradiance:  E_m = sum_q a_{q,m} f_q + R_m      the harmonic set's least squares,
//                                                      when the asset has their exact
//                                                      transfer (normal_harmonics.h)
//                   wR_m = w0 R_m                     Haar per chart, every m and RGB
//                   y_{k,m} = (w1 T_k w0^-1) wR_m      one pass over each sparse matrix
//                                                      (TransferProduct), all m x RGB at once
//   setMaterial:    s_k(sigma, eta) per channel (ProfileProjection), c_m(eta)
//                   z_k = sum_m c_m y_{k,m}            only when eta or the light changes,
//                       + sum_q (sum_m c_m a_{q,m}) w1 (T_k f_q)   with the harmonic transfer
//                   L = w1^-1 ((1/pi) sum_k s_k z_k)   CDF 9/7 inverse per chart
//                   L += (1/pi) R_disk(sigma) E(eta)   the self term, when the asset
//                                                      leaves it to run time (self_term.h)
//                   E = max(0, E), L = max(0, L)       counted (docs/ARCHITECTURE.md#nonnegative-radiance)
//
// L is the subsurface radiance leaving each sample before the outgoing Fresnel factor
// F_t(eta, w_o), which the render pass applies per pixel:
//   L_o(x_o, w_o) = F_t(eta, w_o) L(x_o),  L(x_o) = (1/pi) sum_k s_k (T_k E)(x_o).
// A material edit never touches the sparse matrices: O(K N) (plus O(K M N) when eta
// changes), parallel with TBB.
#pragma once

#include "delegate/relight/float4.h"
#include "delegate/relight/irradiance.h"
#include "delegate/relight/recycled_buffer.h"
#include "delegate/relight/transfer_product.h"
#include "delegate/relight/vertex_gather.h"
#include "schema/asset/normal_harmonics.h"
#include "schema/asset/translucent_asset.h"
#include "schema/scatter/profile_projection.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace opal {

class RelightEngine {
public:
    // Starts with the asset's default material and zero irradiance. Throws opal::Error when
    // the asset's layout, samples, basis and transfer disagree in size.
    explicit RelightEngine(std::shared_ptr<const TranslucentAsset> asset);

    const TranslucentAsset& asset() const { return *asset_; }

    // E_m(x_i) for every sample (1 to 3 moments): the expensive step, then the current
    // material is applied.
    void setIrradiance(const IrradianceMoments& irradiance);
    // Clamps into the asset's editable range (one warning per clamped value, returned),
    // then re-forms the radiance from the cached products.
    std::vector<std::string> setMaterial(const Material& material);
    const Material& material() const { return material_; }  // as clamped

    std::span<const float> sampleRadiance() const { return radiance_; }       // samples x 3
    std::span<const float> vertexRadiance() const { return vertexRadiance_.current(); } // render-mesh vertices x 3
    // The same buffer, for frames to hold. Held buffers never change: the next edit writes
    // into a buffer no one else holds (recycled_buffer.h).
    std::shared_ptr<const std::vector<float>> sharedVertexRadiance() const { return vertexRadiance_.shared(); }
    // E(x_i; eta) = sum_m c_m(eta) E_m(x_i): samples x 3.
    std::span<const float> sampleIrradiance() const { return irradiance_; }
    // The same at the render-mesh vertices (vertices x 3), through the engine's gather:
    // gathered with the radiance whenever E changes (a light or eta), in a buffer held
    // frames never see change, as the radiance's.
    std::shared_ptr<const std::vector<float>> sharedVertexIrradiance() const { return vertexIrradiance_.shared(); }
    // Any per-sample RGB values (samples x 3) at the render-mesh vertices, through the
    // engine's gather and its scratch.
    std::vector<float> toVertices(std::span<const float> perSample);
    // Bytes the engine holds beyond the asset: the compact transfer, products, radiance.
    std::size_t memoryBytes() const;

    // What the last setIrradiance or setMaterial zeroed (L >= 0, E >= 0): the values
    // (sample x channel) the compression's error had taken below zero, and the lowest of
    // them as a fraction of the highest (<= 0; 0 when none; E only when it was re-formed:
    // a new irradiance or eta). Hosts see them in the render stats.
    struct NegativeNoise {
        std::uint64_t values = 0;
        double deepest = 0.0;
    };
    const NegativeNoise& radianceNoise() const { return radianceNoise_; }
    const NegativeNoise& irradianceNoise() const { return irradianceNoise_; }

private:
    void formRadiance(bool reweigh);  // L = w1^-1 ((1/pi) sum_k s_k z_k), then the vertices
    void gatherVertices(bool withIrradiance);  // the vertices' L, and E when it changed
    // How a weighing adds the smooth part of E (weighProducts): not at all (none, or z_k
    // holds it), folded into z_k, or as alpha . G (G refreshed first when s_k changed).
    enum class SmoothPass { None, Fold, ByFunction, RefreshByFunction };
    SmoothPass smoothPass(bool reweigh);
    void weighProducts(bool reweigh, SmoothPass pass, std::size_t begin, std::size_t end);
    void weighSmooth(std::size_t p);  // G(p) for the current s_k
    NegativeNoise addSelfTermAndProject();  // + the self term, then max(0, L); throws unless finite
    void addSmooth(const float (&alpha)[3][kMaxHarmonics], std::size_t p, float* z) const;  // z += the smooth part

    std::shared_ptr<const TranslucentAsset> asset_;
    TransferProduct product_;        // the transfer, compact for y_k (transfer_product.h)
    ProfileProjection projection_;   // s_k(sigma), fitted where the transfer uses the profile
    std::size_t samples_ = 0;
    std::size_t K_ = 0;
    std::size_t paddedK_ = 0;        // K rounded up to a multiple of 4
    std::size_t paddedQ_ = 0;        // the harmonic set's count rounded up to a multiple of 4
    IrradianceMoments moments_;      // E_m as given
    std::vector<float> haar_;        // wE_m = w0 E_m: samples x (3 terms, padded to 4 lanes)
    std::vector<float> input_;       // wE_m in the product's input order (arrangeInput)
    std::vector<float> products_;    // y: samples x K x (3 terms)
    std::optional<HarmonicFit> harmonics_;  // the split of E, when the asset has T_k f_q
    std::vector<float> smooth_;      // w1 U_{k,q} = w1 (T_k f_q): samples x Q x paddedK (9/7 domain)
    std::vector<float> smoothFit_;   // a_{q,m}: Q x (3 terms), from the last setIrradiance
    // G_q = sum_k (s_k / pi) w1 U_{k,q}: samples x 3 x Q padded to 4 (weighProducts)
    std::vector<float> smoothByFunction_;
    bool smoothByFunctionCurrent_ = false;  // G is of the current s_k
    bool smoothInWeighted_ = false;         // z_k holds the smooth part of the current light
    std::vector<float> weighted_;    // z_k = sum_m c_m y_{k,m}: samples x 3 x paddedK
    Material material_;
    std::vector<double> fresnel_;    // c_m(material_.eta)
    std::vector<float> profile_;     // s_k / pi: 3 x paddedK
    std::vector<float> self_;        // R_disk(rho_o; sigma): samples x 3 (empty: in the transfer)
    std::vector<float> radiance_, irradiance_;
    NegativeNoise radianceNoise_, irradianceNoise_;
    RecycledBuffer vertexRadiance_;
    RecycledBuffer vertexIrradiance_;
    VertexGather gather_;            // the render-mesh vertices' weights, in cache-friendly order
    std::vector<Float4> padded_;     // gather_'s scratch
};

// Sets every negative value to zero: how many there were and the lowest as a fraction of
// the highest value (docs/ARCHITECTURE.md#nonnegative-radiance).
RelightEngine::NegativeNoise zeroNegatives(std::span<float> values);


}  // namespace opal
