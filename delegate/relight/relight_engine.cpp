#include "delegate/relight/relight_engine.h"

#include "delegate/relight/float4.h"
#include "delegate/relight/haar_locality_order.h"
#include "delegate/relight/prefetch.h"
#include "delegate/relight/vertex_gather.h"
#include "schema/asset/self_term.h"
#include "schema/error.h"
#include "schema/scatter/fresnel_moments.h"
#include "schema/wavelet/cdf97.h"
#include "schema/wavelet/haar.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <atomic>
#include <array>
#include <cstring>
#include <numbers>
#include <string>
#include <utility>

namespace opal {

namespace {

constexpr std::uint32_t kRowsPerTask = 256;
// How many samples ahead a light edit's weighing prefetches the products y and G
// (prefetch.h). Its weighing on the 65,536-sample bunny's point-light move (a temporary
// stopwatch, medians, 2026-11-28): none 3.86-3.89 ms; 2 samples 2.80; 4 2.63-2.65; 8 2.74-2.78;
// 16 2.65. A material edit's weighing reads only z_k, which prefetching did not speed up.
constexpr std::size_t kWeighPrefetchSamples = 4;
constexpr std::size_t kValuesPerTask = 32768;  // per-sample passes over samples x 3 floats


void checkAsset(const TranslucentAsset& asset) {
    const std::size_t n = asset.layout.cells();
    const auto fail = [&](const std::string& what) {
        throw Error("relight engine: asset '" + asset.name + "': " + what);
    };
    if (n == 0 || asset.samples.size() != n)
        fail(std::to_string(asset.samples.size()) + " samples for a layout of " + std::to_string(n) + " cells");
    if (asset.transfer.perBasis.size() != std::size_t(asset.basis.K()))
        fail(std::to_string(asset.transfer.perBasis.size()) + " transfer matrices for K = " +
             std::to_string(asset.basis.K()) + " basis functions");
    for (const SparseMatrix& m : asset.transfer.perBasis)
        if (m.rows != n || m.cols != n || m.rowOffsets.size() != n + 1)
            fail("a transfer matrix is " + std::to_string(m.rows) + " x " + std::to_string(m.cols) + ", expected " +
                 std::to_string(n) + " x " + std::to_string(n));
}

// The asset's transfer, after checkAsset: what the product copy is built from.
TransferProduct checkedTransfer(const std::shared_ptr<const TranslucentAsset>& asset) {
    if (!asset) throw Error("relight engine: no asset");
    checkAsset(*asset);
    return TransferProduct(asset->transfer, asset->samples.size(), TransferProduct::Kernel::Best,
                           haarLocalitySlots(asset->layout));
}

// values[i] = max(0, update(i, values[i])) in one parallel pass: how many were negative and
// how deep (zeroNegatives), and whether every updated value was finite (sum v * 0 is 0
// exactly when every v is).
struct Projected {
    RelightEngine::NegativeNoise noise;
    bool finite = true;
};

using Int4 = std::int32_t __attribute__((vector_size(16)));  // lane masks: -1 set, 0 clear
constexpr Int4 kEveryLane = {-1, -1, -1, -1}, kFirstLane = {-1, 0, 0, 0};

// a where mask is set, else b, lane by lane.
inline Float4 select(Int4 mask, Float4 a, Float4 b) { return Float4((Int4(a) & mask) | (Int4(b) & ~mask)); }

// The pass's running figures, four lanes wide. With one float of each, every value waited
// for the previous value's add (GCC keeps float sums in order): the self term's pass of a
// material edit on the 65,536-sample bunny took 0.12 ms, 0.06 ms this way.
struct Extremes {
    Float4 lowest = {}, highest = {}, zero = {};
    Int4 negative = {};  // minus the count per lane

    // v's lanes where keep is set.
    void add(Float4 v, Int4 keep) {
        lowest = select((v < lowest) & keep, v, lowest);
        highest = select((highest < v) & keep, v, highest);
        zero += select(keep, v * 0.0f, Float4{});
        negative += (v < 0.0f) & keep;
    }
    void merge(const Extremes& o) {
        lowest = select(o.lowest < lowest, o.lowest, lowest);
        highest = select(highest < o.highest, o.highest, highest);
        zero += o.zero;
        negative += o.negative;
    }
};

// max(v, 0) lane by lane; NaN stays NaN, for the finite check to report.
inline Float4 nonNegative(Float4 v) { return select(v < 0.0f, Float4{}, v); }

template <typename Update>
Projected projectNonNegative(std::span<float> values, const Update& update) {
    const Extremes e = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, values.size(), kValuesPerTask), Extremes{},
        [&](const tbb::blocked_range<std::size_t>& r, Extremes so) {
            std::size_t i = r.begin();
            for (; i + 4 <= r.end(); i += 4) {
                const Float4 v = {update(i, values[i]), update(i + 1, values[i + 1]), update(i + 2, values[i + 2]),
                                  update(i + 3, values[i + 3])};
                so.add(v, kEveryLane);
                store4(values.data() + i, nonNegative(v));
            }
            for (; i != r.end(); ++i) {
                const Float4 v = {update(i, values[i]), 0.0f, 0.0f, 0.0f};
                so.add(v, kFirstLane);
                values[i] = nonNegative(v)[0];
            }
            return so;
        },
        [](Extremes a, const Extremes& b) {
            a.merge(b);
            return a;
        });
    float lowest = 0.0f, highest = 0.0f, zero = 0.0f;
    std::uint64_t count = 0;
    for (int l = 0; l < 4; ++l) {
        lowest = std::min(lowest, e.lowest[l]);
        highest = std::max(highest, e.highest[l]);
        zero += e.zero[l];
        count += std::uint64_t(-e.negative[l]);
    }
    return {{count, highest > 0.0f ? double(lowest) / double(highest) : 0.0}, zero == 0.0f};
}

}  // namespace

RelightEngine::RelightEngine(std::shared_ptr<const TranslucentAsset> asset)
    : asset_(std::move(asset)),
      product_(checkedTransfer(asset_)),
      projection_(asset_->basis, profileFitRadius(*asset_)),
      gather_(asset_->vertexWeights, asset_->samples.size()) {
    samples_ = asset_->samples.size();
    K_ = asset_->transfer.perBasis.size();
    paddedK_ = (K_ + 3) / 4 * 4;
    moments_ = IrradianceMoments(std::uint32_t(samples_), 1);
    products_.assign(K_ * samples_ * 3, 0.0f);
    if (!asset_->transfer.harmonics.empty()) {
        harmonics_.emplace(asset_->samples, asset_->transfer.harmonicSet);
        // w1 U_{k,q}: the 9/7 transform over outputs, then laid out [p][q][paddedK] for the
        // weighing's K-wide lanes.
        const std::size_t Q = harmonics_->count();
        paddedQ_ = (Q + 3) / 4 * 4;
        std::vector<float> w1U = asset_->transfer.harmonics;
        cdf97ForwardCharts(std::span<float>(w1U), asset_->layout, std::uint32_t(K_ * Q));
        smooth_.assign(samples_ * Q * paddedK_, 0.0f);
        for (std::size_t p = 0; p < samples_; ++p)
            for (std::size_t k = 0; k < K_; ++k)
                for (std::size_t q = 0; q < Q; ++q) smooth_[(p * Q + q) * paddedK_ + k] = w1U[(p * K_ + k) * Q + q];
    }
    material_.eta = 0.0;  // forces the first setMaterial to weigh the products
    setMaterial(asset_->defaultMaterial);
}

void RelightEngine::setIrradiance(const IrradianceMoments& irradiance) {
    if (irradiance.samples != samples_ || irradiance.terms < 1 || irradiance.terms > std::uint32_t(kMaxFresnelTerms) ||
        irradiance.values.size() != samples_ * irradiance.channels())
        throw Error("relight engine: irradiance of " + std::to_string(irradiance.samples) + " samples x " +
                    std::to_string(irradiance.terms) + " moments for an asset of " + std::to_string(samples_) +
                    " samples (1 to 3 moments)");
    const std::size_t C = irradiance.channels(), W = (C + 3) / 4 * 4;
    // wE = w0 E: every moment and channel at once, padded to W lanes; with the harmonics,
    // w0 of E's residual after its smooth part (docs/ARCHITECTURE.md#harmonic-transfer).
    haar_.assign(samples_ * W, 0.0f);
    if (harmonics_) {
        smoothFit_ = harmonics_->coefficients(irradiance.values, C);
        harmonics_->residual(irradiance.values, C, smoothFit_, haar_, W);
    } else {
        for (std::size_t i = 0; i < samples_; ++i) std::copy_n(irradiance.sample(i), C, haar_.data() + i * W);
    }
    haarForwardCharts(std::span<float>(haar_), asset_->layout, std::uint32_t(W));
    input_.resize(haar_.size());
    product_.arrangeInput(haar_, W, input_);

    // y_{k,m} = (w1 T_k w0^-1) wE_m, one task per block of the product's stored rows.
    products_.resize(samples_ * K_ * C);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, std::uint32_t(samples_), kRowsPerTask),
                      [&](const tbb::blocked_range<std::uint32_t>& rows) {
                          product_.multiplyRows(input_.data(), W, products_.data(), C, rows.begin(), rows.end());
                      });
    moments_ = irradiance;
    fresnel_ = fresnelMoments(material_.eta, int(moments_.terms), moments_.basis);
    formRadiance(true);
}

std::vector<std::string> RelightEngine::setMaterial(const Material& material) {
    std::vector<std::string> warnings;
    const Material clamped = asset_->range.clamp(material, &warnings);
    // s_k(sigma, eta) and the self term's R_disk depend on the material alone: side by side.
    std::array<std::vector<double>, 3> s;
    tbb::parallel_invoke([&] { s = projection_.project(clamped); },
                         [&] {
                             if (asset_->transfer.selfTerm != SelfTerm::AtRunTime) return;
                             self_.resize(samples_ * 3);
                             selfTermReflectance(asset_->samples, asset_->unitsPerMm, clamped, self_);
                         });
    profile_.assign(3 * paddedK_, 0.0f);
    for (int c = 0; c < 3; ++c)
        for (std::size_t k = 0; k < K_; ++k) profile_[c * paddedK_ + k] = float(s[c][k] / std::numbers::pi);
    const bool etaChanged = clamped.eta != material_.eta;
    material_ = clamped;
    smoothByFunctionCurrent_ = false;  // G is of the previous s_k
    if (etaChanged) fresnel_ = fresnelMoments(material_.eta, int(moments_.terms), moments_.basis);
    formRadiance(etaChanged);
    return warnings;
}

// sum_k (s_k / pi) z_k(p) per channel, where z_k = sum_m c_m y_{k,m} is the eta-dependent
// part: re-weighed from the products (and kept) when eta changed, else read back, so that
// a sigma edit only weighs K values per channel. z and s/pi are stored channel by channel
// with K padded to whole registers (the padding stays zero).
//
// With the harmonic transfer, L also gets the smooth part of E, exact
// (docs/ARCHITECTURE.md#harmonic-transfer):
//   sum_k (s_k / pi) sum_q alpha_q w1 U_{k,q},   alpha_q = sum_m c_m a_{q,m}
// Reading w1 U (K x Q values a sample) is most of a light edit's weighing, so it is read
// once per change of kind (SmoothPass): a light or eta change adds alpha . G with
// G_q = sum_k (s_k / pi) w1 U_{k,q}, kept while the material stays; a sigma edit after a
// light change folds sum_q alpha_q w1 U_{k,q} into z_k, kept while the light stays.
void RelightEngine::weighProducts(bool reweigh, SmoothPass pass, std::size_t begin, std::size_t end) {
    const std::size_t terms = moments_.terms, C = 3 * terms;
    float c[kMaxFresnelTerms];
    for (std::size_t m = 0; m < terms; ++m) c[m] = float(fresnel_[m]);
    const std::size_t Q = harmonics_ ? harmonics_->count() : 0;
    float alpha[3][kMaxHarmonics] = {};  // zero beyond Q: the padding of G
    if (pass != SmoothPass::None)
        for (std::size_t ch = 0; ch < 3; ++ch)
            for (std::size_t q = 0; q < Q; ++q)
                for (std::size_t m = 0; m < terms; ++m) alpha[ch][q] += c[m] * smoothFit_[q * C + 3 * m + ch];
    const bool byFunction = pass == SmoothPass::ByFunction || pass == SmoothPass::RefreshByFunction;
    for (std::size_t p = begin; p != end; ++p) {
        float* z = weighted_.data() + p * 3 * paddedK_;
        if (reweigh) {
            const float* y = products_.data() + p * K_ * C;
            prefetchRangeAhead(y, kWeighPrefetchSamples * K_ * C * sizeof(float), K_ * C * sizeof(float));
            if (byFunction) {
                const std::size_t row = 3 * paddedQ_ * sizeof(float);
                prefetchRangeAhead(smoothByFunction_.data() + p * 3 * paddedQ_, kWeighPrefetchSamples * row, row);
            }
            for (std::size_t ch = 0; ch < 3; ++ch)
                for (std::size_t k = 0; k < K_; ++k) {
                    float sum = 0.0f;
                    for (std::size_t m = 0; m < terms; ++m) sum += c[m] * y[k * C + 3 * m + ch];
                    z[ch * paddedK_ + k] = sum;
                }
        }
        if (pass == SmoothPass::Fold) addSmooth(alpha, p, z);
        if (pass == SmoothPass::RefreshByFunction) weighSmooth(p);
        const float* g = byFunction ? smoothByFunction_.data() + p * 3 * paddedQ_ : nullptr;
        for (std::size_t ch = 0; ch < 3; ++ch) {
            Float4 sum = {};
            for (std::size_t k = 0; k < paddedK_; k += 4)
                sum += load4(profile_.data() + ch * paddedK_ + k) * load4(z + ch * paddedK_ + k);
            if (byFunction)
                for (std::size_t q = 0; q < paddedQ_; q += 4) sum += load4(alpha[ch] + q) * load4(g + ch * paddedQ_ + q);
            radiance_[p * 3 + ch] = (sum[0] + sum[1]) + (sum[2] + sum[3]);
        }
    }
}

// G_q(p) = sum_k (s_k / pi) w1 U_{k,q}(p) per channel, Q padded to whole registers.
void RelightEngine::weighSmooth(std::size_t p) {
    const std::size_t Q = harmonics_->count();
    const float* u = smooth_.data() + p * Q * paddedK_;
    float* g = smoothByFunction_.data() + p * 3 * paddedQ_;
    for (std::size_t ch = 0; ch < 3; ++ch)
        for (std::size_t q = 0; q < Q; ++q) {
            Float4 sum = {};
            for (std::size_t k = 0; k < paddedK_; k += 4)
                sum += load4(profile_.data() + ch * paddedK_ + k) * load4(u + q * paddedK_ + k);
            g[ch * paddedQ_ + q] = (sum[0] + sum[1]) + (sum[2] + sum[3]);
        }
}

namespace {

using Float16Lanes = float __attribute__((vector_size(16 * sizeof(float))));

// How far ahead of the row of w1 U being folded addSmooth16 prefetches it (prefetch.h).
// material_after_light on the 65,536-sample bunny (opal-bench relight, medians,
// 2026-11-28): none 10.1-10.2 ms; 1 KB 8.4; 2 KB 8.1; 4 KB 8.2; 8 KB 8.3.
constexpr std::size_t kFoldPrefetchBytes = 2048;

// addSmooth for 16 k at a time (K = 16, the default basis): each u_q read once, the three
// channels' sums held in registers, three independent chains of Q multiply-adds. Four k at
// a time, each sum is one chain of Q dependent multiply-adds (latency-bound). Measured on
// the 65,536-sample bunny with the 36 functions, `opal-bench relight`'s
// material_after_light (the edit that folds the smooth part into z_k): 11.2-11.3 ms this
// way, 17.4-17.6 ms four k at a time; a material edit that does not fold takes 1.8-2.0 ms
// (2026-11-27; with the prefetch below, 8.1 ms, 2026-11-28).
// The fold reads w1 U, 151 MB: about 6 ms at the triad bandwidth measured then.
__attribute__((target_clones("avx512f", "avx2", "default"))) void addSmooth16(
    const float (&alpha)[3][kMaxHarmonics], std::size_t Q, const float* u, float* z) {
    Float16Lanes sum[3];
    std::memcpy(sum, z, sizeof(sum));
    for (std::size_t q = 0; q < Q; ++q) {
        prefetchAhead(u + q * 16, kFoldPrefetchBytes);
        Float16Lanes uq;
        std::memcpy(&uq, u + q * 16, sizeof(uq));
        sum[0] += alpha[0][q] * uq;
        sum[1] += alpha[1][q] * uq;
        sum[2] += alpha[2][q] * uq;
    }
    std::memcpy(z, sum, sizeof(sum));
}

}  // namespace

// z[ch][k] += sum_q alpha[ch][q] w1 U_{k,q}(p) (the padding stays zero).
void RelightEngine::addSmooth(const float (&alpha)[3][kMaxHarmonics], std::size_t p, float* z) const {
    const std::size_t Q = harmonics_->count();
    const float* u = smooth_.data() + p * Q * paddedK_;
    if (paddedK_ == 16) return addSmooth16(alpha, Q, u, z);
    for (std::size_t ch = 0; ch < 3; ++ch)
        for (std::size_t k = 0; k < paddedK_; k += 4) {
            Float4 sum = load4(z + ch * paddedK_ + k);
            for (std::size_t q = 0; q < Q; ++q) sum += alpha[ch][q] * load4(u + q * paddedK_ + k);
            store4(z + ch * paddedK_ + k, sum);
        }
}

// Which way the smooth part goes in this weighing (weighProducts), and what it leaves kept.
RelightEngine::SmoothPass RelightEngine::smoothPass(bool reweigh) {
    const std::size_t C = 3 * moments_.terms;
    if (!harmonics_ || smoothFit_.size() != harmonics_->count() * C) return SmoothPass::None;
    if (reweigh) {  // a new light or eta: z_k lacks it now; G holds it if the material stayed
        smoothInWeighted_ = false;
        const bool current = smoothByFunctionCurrent_;
        smoothByFunctionCurrent_ = true;
        return current ? SmoothPass::ByFunction : SmoothPass::RefreshByFunction;
    }
    if (smoothInWeighted_) return SmoothPass::None;  // a sigma edit, z_k holds it already
    smoothInWeighted_ = true;
    return SmoothPass::Fold;
}

// L = w1^-1 ((1/pi) sum_k s_k z_k), per channel; then the render-mesh vertices, and E(eta).
void RelightEngine::formRadiance(bool reweigh) {
    radiance_.resize(samples_ * 3);
    weighted_.resize(samples_ * 3 * paddedK_);
    const SmoothPass pass = smoothPass(reweigh);
    if (pass == SmoothPass::RefreshByFunction) smoothByFunction_.resize(samples_ * 3 * paddedQ_);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples_, 2048), [&](const tbb::blocked_range<std::size_t>& r) {
        weighProducts(reweigh, pass, r.begin(), r.end());
    });
    cdf97InverseCharts(std::span<float>(radiance_), asset_->layout, 3);
    irradianceNoise_ = {};  // E is re-formed (and zeroed) only when eta or the lights changed
    if (reweigh) {
        moments_.combine(fresnel_, irradiance_);
        irradianceNoise_ = zeroNegatives(irradiance_);
    }
    radianceNoise_ = addSelfTermAndProject();
    gatherVertices(reweigh);
}

// The vertices' L, and their E when it was formed again: both in one pass over the weights.
void RelightEngine::gatherVertices(bool withIrradiance) {
    std::vector<float>& radiance = vertexRadiance_.next();
    radiance.resize(gather_.vertices() * 3);
    if (!withIrradiance) {
        if (!radiance.empty()) gather_.apply(radiance_, radiance, padded_);
        return;
    }
    std::vector<float>& irradiance = vertexIrradiance_.next();
    irradiance.resize(gather_.vertices() * 3);
    if (!radiance.empty()) gather_.apply(radiance_, irradiance_, radiance, irradiance, padded_);
}

std::vector<float> RelightEngine::toVertices(std::span<const float> perSample) {
    std::vector<float> out(gather_.vertices() * 3);
    if (!out.empty()) gather_.apply(perSample, out, padded_);
    return out;
}

// L(x_o) += (1/pi) R_disk(rho_o; sigma) E(x_o; eta), in the sample domain (after the 9/7
// inverse): the self term the bake left out of the transfer (docs/ARCHITECTURE.md#self-term);
// then L = max(0, L) in the same pass.
// Lights are bounded (light_emission.h) so that every sum stays finite for transfer values
// a bake can produce; a sidecar whose values are finite but absurd (damaged, or written by
// something else) could still overflow, and must not reach an image as NaN or infinity.
RelightEngine::NegativeNoise RelightEngine::addSelfTermAndProject() {
    const float* self = self_.empty() ? nullptr : self_.data();
    const float* irradiance = irradiance_.data();
    constexpr float invPi = float(1.0 / std::numbers::pi);
    const Projected projected = self ? projectNonNegative(radiance_, [=](std::size_t i, float v) { return v + invPi * self[i] * irradiance[i]; })
                                     : projectNonNegative(radiance_, [](std::size_t, float v) { return v; });
    if (!projected.finite)
        throw Error("asset '" + asset_->name +
                    "': the relit radiance is not finite: the sidecar's transfer values are out of range (re-bake it)");
    return projected.noise;
}

// Radiance is never negative, and neither is the exact L at any sample: a nonnegative
// profile gathers nonnegative E. The compressed transfer adds an error of either sign
// (about 1e-3 of the peak at the defaults), which takes L below zero only where the true
// L is smaller than that error: the unlit samples, lit through the profile's far tail
// alone. A dome's E has the same kind of error from its truncated visibility vectors.
// Setting those values to zero is the projection onto a set that holds the truth, so it
// moves every value toward the truth, never away; the count and the depth stay visible
// (docs/ARCHITECTURE.md#nonnegative-radiance).
RelightEngine::NegativeNoise zeroNegatives(std::span<float> values) {
    return projectNonNegative(values, [](std::size_t, float v) { return v; }).noise;
}

namespace {

template <typename T>
std::size_t bytesOf(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

}  // namespace

std::size_t RelightEngine::memoryBytes() const {
    return product_.memoryBytes() + bytesOf(moments_.values) + bytesOf(haar_) + bytesOf(input_) + bytesOf(products_) +
           bytesOf(weighted_) + bytesOf(fresnel_) + bytesOf(profile_) + bytesOf(self_) + bytesOf(radiance_) + bytesOf(irradiance_) +
           vertexRadiance_.memoryBytes() + vertexIrradiance_.memoryBytes() + bytesOf(padded_) +
           gather_.memoryBytes() + bytesOf(smooth_) + bytesOf(smoothByFunction_) +
           (harmonics_ ? harmonics_->patterns().size_bytes() : 0);
}

}  // namespace opal
