#include "delegate/relight/relight_engine.h"

#include "schema/asset/normal_harmonics.h"
#include "schema/asset/self_term.h"
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "synthetic_asset.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numbers>
#include <random>
#include <string>

namespace opal {
namespace {

// A slab of 2 charts of 16 x 16 samples, 0.25 mm apart (spacing in scene units of 0.1 mm),
// with the lossless transfer.
std::shared_ptr<TranslucentAsset> slabAsset(double keepFraction = 1.0, double energyFraction = 1.0,
                                            SelfTerm selfTerm = SelfTerm::InTransfer, float spacing = 2.5f) {
    auto asset = std::make_shared<TranslucentAsset>();
    asset->name = "slab";
    asset->unitsPerMm = 10.0;  // scene units are 0.1 mm
    test::makeSlab(*asset, 2, 1, 4, spacing);
    asset->defaultMaterial = Material{{1.0, 0.8, 0.6}, {0.05, 0.1, 0.2}, 1.3};
    asset->range = test::rangeAround(asset->defaultMaterial, 3.0, 1.2, 1.6);
    asset->basis = test::fitBasis(asset->range, 8, 12.0);
    test::buildTransfer(*asset, keepFraction, energyFraction, selfTerm);
    // Each vertex blends two samples.
    const std::size_t n = asset->samples.size();
    for (std::size_t v = 0; v < n; ++v) {
        asset->vertexWeights.offsets.push_back(std::uint32_t(2 * v));
        asset->vertexWeights.samples.insert(asset->vertexWeights.samples.end(), {std::uint32_t(v), std::uint32_t((v + 1) % n)});
        asset->vertexWeights.weights.insert(asset->vertexWeights.weights.end(), {0.25f, 0.75f});
    }
    asset->vertexWeights.offsets.push_back(std::uint32_t(2 * n));
    return asset;
}

// L = (1/pi) sum_k s_k T_k E with the dense T_k and E = sum_m c_m E_m: the direct evaluation.
// The engine multiplies with binary16 transfer values (transfer_product.h, relative rounding
// <= 2^-11 per entry), so it matches this to kHalfProduct rather than float precision.
constexpr double kHalfProduct = 1e-3;

// With the self term left to run time, the diagonal is the dipole's disk reflectance
// (closed form, docs/ARCHITECTURE.md#total-reflectance) times E_o.
std::vector<float> directRadiance(const TranslucentAsset& asset, const Material& material,
                                  const IrradianceMoments& moments) {
    const std::size_t n = asset.samples.size();
    const std::vector<float> e = moments.combine(fresnelMoments(material.eta, int(moments.terms)));
    const std::array<std::vector<double>, 3> s =
        ProfileProjection(asset.basis, profileFitRadius(asset)).project(material);  // plain when InTransfer
    std::vector<double> sum(3 * n, 0.0);
    if (asset.transfer.selfTerm == SelfTerm::AtRunTime)
        for (std::size_t o = 0; o < n; ++o)
            for (int c = 0; c < 3; ++c) {
                const double radius = std::sqrt(asset.samples[o].area / std::numbers::pi) / asset.unitsPerMm;
                sum[3 * o + c] = dipoleDiskReflectance(radius, material.channel(c)) * e[3 * o + c];
            }
    for (int k = 0; k < asset.basis.K(); ++k) {
        const std::vector<double> t = test::denseTransfer(asset, k, asset.transfer.selfTerm);
        for (std::size_t o = 0; o < n; ++o)
            for (std::size_t i = 0; i < n; ++i)
                for (int c = 0; c < 3; ++c) sum[3 * o + c] += s[c][k] * t[o * n + i] * e[3 * i + c];
    }
    std::vector<float> radiance(3 * n);
    for (std::size_t j = 0; j < radiance.size(); ++j) radiance[j] = float(sum[j] / std::numbers::pi);
    return radiance;
}

TEST(RelightEngine, LosslessTransferMatchesTheDenseProduct) {
    const auto asset = slabAsset();
    for (std::uint32_t terms : {1u, 2u, 3u}) {  // 3, 6 and 9 interleaved channels
        const IrradianceMoments moments = test::randomMoments(std::uint32_t(asset->samples.size()), terms, 11 + terms);
        RelightEngine engine(asset);
        engine.setIrradiance(moments);
        EXPECT_LT(test::maxRelative(engine.sampleRadiance(), directRadiance(*asset, asset->defaultMaterial, moments)),
                  kHalfProduct)
            << terms << " terms";
        EXPECT_LT(test::maxRelative(engine.sampleIrradiance(),
                                    moments.combine(fresnelMoments(asset->defaultMaterial.eta, int(terms)))),
                  1e-7);
    }
}

// Finite transfer values no bake produces (a damaged sidecar with valid checksums): the
// product overflows, and the engine refuses to hand out NaN or infinite radiance.
TEST(RelightEngine, AbsurdTransferValuesAreAnErrorNotNaNInTheImage) {
    auto asset = slabAsset();
    for (float& v : asset->transfer.perBasis[0].values) v = v >= 0.0f ? 3e38f : -3e38f;
    RelightEngine engine(asset);
    try {
        engine.setIrradiance(test::randomMoments(std::uint32_t(asset->samples.size()), 2, 5));
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("asset 'slab': the relit radiance is not finite"), std::string::npos)
            << e.what();
    }
}

TEST(RelightEngine, MaterialEditsEqualAFullRecompute) {
    const auto asset = slabAsset();
    const IrradianceMoments moments = test::randomMoments(std::uint32_t(asset->samples.size()), 2, 5);
    RelightEngine edited(asset);
    edited.setIrradiance(moments);
    const Material edits[] = {
        {{1.4, 0.7, 0.5}, {0.04, 0.12, 0.3}, 1.3},  // sigma only
        {{1.4, 0.7, 0.5}, {0.04, 0.12, 0.3}, 1.5},  // eta only
        {{0.6, 1.1, 0.9}, {0.1, 0.06, 0.08}, 1.25}, // both
        {{0.6, 1.1, 0.9}, {0.02, 0.06, 0.08}, 1.25},
    };
    for (const Material& m : edits) {
        EXPECT_TRUE(edited.setMaterial(m).empty());
        RelightEngine fresh(asset);
        fresh.setMaterial(m);
        fresh.setIrradiance(moments);
        EXPECT_LT(test::maxRelative(edited.sampleRadiance(), fresh.sampleRadiance()), 1e-5);
        EXPECT_LT(test::maxRelative(edited.sampleRadiance(), directRadiance(*asset, m, moments)), kHalfProduct);
        EXPECT_LT(test::maxRelative(edited.vertexRadiance(), fresh.vertexRadiance()), 1e-5);
    }
}

// A sphere of 384 samples with K basis functions, the lossless transfer and the 36-function
// harmonic transfer computed from the same dense T_k: U_{k,q}[o] = sum_i T_k[o][i] f_q(x_i, n_i).
std::shared_ptr<TranslucentAsset> sphereWithHarmonics(int K) {
    auto asset = std::make_shared<TranslucentAsset>();
    asset->name = "sphere";
    test::makeCubeSphere(*asset, 3, 5.0f);
    asset->defaultMaterial = Material{{1.0, 0.8, 0.6}, {0.05, 0.1, 0.2}, 1.3};
    asset->range = test::rangeAround(asset->defaultMaterial, 3.0, 1.2, 1.6);
    asset->basis = test::fitBasis(asset->range, K, 12.0);
    test::buildTransfer(*asset, 1.0, 1.0, SelfTerm::AtRunTime);
    const std::size_t n = asset->samples.size();
    HarmonicSet& set = asset->transfer.harmonicSet;
    set = harmonicSetFor(asset->samples);
    std::vector<float> f(n * set.count);
    for (std::size_t i = 0; i < n; ++i)
        harmonicValues(set, asset->samples[i], std::span<float>(f).subspan(i * set.count, set.count));
    asset->transfer.harmonics.assign(n * std::size_t(K) * set.count, 0.0f);
    for (int k = 0; k < K; ++k) {
        const std::vector<double> t = test::denseTransfer(*asset, k, SelfTerm::AtRunTime);
        for (std::size_t o = 0; o < n; ++o)
            for (std::size_t q = 0; q < set.count; ++q) {
                double sum = 0.0;
                for (std::size_t i = 0; i < n; ++i) sum += t[o * n + i] * f[i * set.count + q];
                asset->transfer.harmonics[(o * std::size_t(K) + std::size_t(k)) * set.count + q] = float(sum);
            }
    }
    for (std::size_t v = 0; v < asset->mesh.points.size(); ++v) {
        asset->vertexWeights.offsets.push_back(std::uint32_t(v));
        asset->vertexWeights.samples.push_back(std::uint32_t(v % n));
        asset->vertexWeights.weights.push_back(1.0f);
    }
    asset->vertexWeights.offsets.push_back(std::uint32_t(asset->mesh.points.size()));
    return asset;
}

// The smooth part of E reaches L one of two ways (RelightEngine::weighProducts): folded into
// z_k after a material edit, or through G = sum_k s_k w1 U_k after a light or eta change,
// G kept while the material stays. Any sequence of edits gives a fresh engine's radiance,
// and the direct dense sum. K = 8 and K = 16 (the default, whose fold runs 16 k at a time).
void expectSmoothPartThroughAnySequenceOfEdits(int K) {
    SCOPED_TRACE(K);
    const auto asset = sphereWithHarmonics(K);
    const auto n = std::uint32_t(asset->samples.size());
    const IrradianceMoments lights[] = {test::randomMoments(n, 2, 5), test::randomMoments(n, 2, 6),
                                        test::randomMoments(n, 2, 7)};
    const Material materials[] = {
        {{1.4, 0.7, 0.5}, {0.04, 0.12, 0.3}, 1.3},   // sigma only
        {{1.1, 0.9, 0.5}, {0.06, 0.1, 0.25}, 1.3},   // sigma only
        {{1.1, 0.9, 0.5}, {0.06, 0.1, 0.25}, 1.45},  // eta only
    };
    // (light index, material index) per step: light and material edits in runs and alone.
    const std::pair<int, int> steps[] = {{0, 0}, {0, 1}, {1, 1}, {2, 1}, {2, 0}, {2, 1}, {0, 2}, {1, 2}, {1, 0}};
    RelightEngine edited(asset);
    edited.setIrradiance(lights[0]);
    int light = 0;
    for (const auto& [l, m] : steps) {
        SCOPED_TRACE(testing::Message() << "light " << l << ", material " << m);
        if (l != light) edited.setIrradiance(lights[l]);
        light = l;
        edited.setMaterial(materials[m]);
        RelightEngine fresh(asset);
        fresh.setMaterial(materials[m]);
        fresh.setIrradiance(lights[l]);
        EXPECT_LT(test::maxRelative(edited.sampleRadiance(), fresh.sampleRadiance()), 1e-5);
        EXPECT_LT(test::maxRelative(edited.sampleRadiance(), directRadiance(*asset, materials[m], lights[l])),
                  kHalfProduct);
    }
}

TEST(RelightEngine, SmoothPartThroughAnySequenceOfEditsEqualsAFullRecompute) {
    expectSmoothPartThroughAnySequenceOfEdits(8);
    expectSmoothPartThroughAnySequenceOfEdits(16);
}

// The self term left to run time is the dipole's exact disk reflectance of the current
// material, through sigma and eta edits alike. (At the short corner the s_k are large and
// of both signs, so the binary16 products' rounding cancels less: 1.09e-3 there, and
// 1.25e-3 with the self term in the transfer.)
TEST(RelightEngine, SelfTermAtRunTimeIsTheDiskReflectanceOfTheCurrentMaterial) {
    const auto asset = slabAsset(1.0, 1.0, SelfTerm::AtRunTime);
    const IrradianceMoments moments = test::randomMoments(std::uint32_t(asset->samples.size()), 2, 7);
    RelightEngine engine(asset);
    engine.setIrradiance(moments);
    EXPECT_LT(test::maxRelative(engine.sampleRadiance(), directRadiance(*asset, asset->defaultMaterial, moments)),
              kHalfProduct);
    for (const Material& m : {Material{{2.9, 2.5, 2.0}, {0.5, 0.4, 0.3}, 1.3},     // the short corner
                              Material{{0.4, 0.35, 0.3}, {0.02, 0.04, 0.07}, 1.5}}) { // long, other eta
        EXPECT_TRUE(engine.setMaterial(m).empty());
        EXPECT_LT(test::maxRelative(engine.sampleRadiance(), directRadiance(*asset, m, moments)), 1.5 * kHalfProduct)
            << m.sigmaSPrime[0];
    }
}

TEST(RelightEngine, HeldVertexRadianceNeverChangesAndFreeBuffersAreReused) {
    const auto asset = slabAsset();
    RelightEngine engine(asset);
    engine.setIrradiance(test::randomMoments(std::uint32_t(asset->samples.size()), 2, 9));
    const Material a{{1.4, 0.7, 0.5}, {0.04, 0.12, 0.3}, 1.3}, b{{0.6, 1.1, 0.9}, {0.1, 0.06, 0.08}, 1.25};
    // A host holding each frame: every edit gets a buffer of its own.
    std::shared_ptr<const std::vector<float>> first = engine.sharedVertexRadiance();
    const std::vector<float> firstValues = *first;
    engine.setMaterial(a);
    std::shared_ptr<const std::vector<float>> second = engine.sharedVertexRadiance();
    const std::vector<float> secondValues = *second;
    engine.setMaterial(b);
    EXPECT_EQ(*first, firstValues);
    EXPECT_EQ(*second, secondValues);
    EXPECT_NE(*engine.sharedVertexRadiance(), secondValues);
    EXPECT_EQ(std::span<const float>(*engine.sharedVertexRadiance()).data(), engine.vertexRadiance().data());
    // A host keeping only the last frame: two buffers alternate, nothing is allocated.
    first.reset(), second.reset();
    std::shared_ptr<const std::vector<float>> held = engine.sharedVertexRadiance();
    const std::vector<float>* previous = held.get();
    engine.setMaterial(a);
    held = engine.sharedVertexRadiance();
    const std::vector<float>* current = held.get();
    EXPECT_NE(current, previous);
    engine.setMaterial(b);
    held = engine.sharedVertexRadiance();
    EXPECT_EQ(held.get(), previous);
    engine.setMaterial(a);
    EXPECT_EQ(engine.sharedVertexRadiance().get(), current);
}

TEST(RelightEngine, VertexIrradianceIsGatheredOncePerIrradianceAndHeldBuffersNeverChange) {
    const auto asset = slabAsset();
    RelightEngine engine(asset);
    engine.setIrradiance(test::randomMoments(std::uint32_t(asset->samples.size()), 2, 5));
    std::shared_ptr<const std::vector<float>> first = engine.sharedVertexIrradiance();
    EXPECT_EQ(*first, engine.toVertices(engine.sampleIrradiance()));
    const std::vector<float> firstValues = *first;
    // A material edit that keeps eta keeps E: the same buffer, not gathered again.
    Material m = engine.material();
    m.sigmaA[0] *= 1.5;
    engine.setMaterial(m);
    EXPECT_EQ(engine.sharedVertexIrradiance().get(), first.get());
    // New light: new values in another buffer; the held one is as it was.
    engine.setIrradiance(test::randomMoments(std::uint32_t(asset->samples.size()), 2, 6));
    std::shared_ptr<const std::vector<float>> second = engine.sharedVertexIrradiance();
    EXPECT_NE(second.get(), first.get());
    EXPECT_EQ(*first, firstValues);
    EXPECT_EQ(*second, engine.toVertices(engine.sampleIrradiance()));
    EXPECT_NE(*second, firstValues);
    // So does an eta edit (E depends on eta through the Fresnel moments).
    m.eta += 0.05;
    engine.setMaterial(m);
    EXPECT_EQ(*engine.sharedVertexIrradiance(), engine.toVertices(engine.sampleIrradiance()));
    EXPECT_NE(*engine.sharedVertexIrradiance(), *second);
    // Nobody holding the old buffers: the engine writes into them again.
    const std::vector<float>* held = engine.sharedVertexIrradiance().get();
    first.reset(), second.reset();
    engine.setIrradiance(test::randomMoments(std::uint32_t(asset->samples.size()), 2, 7));
    EXPECT_EQ(engine.sharedVertexIrradiance().get(), held);
}

TEST(RelightEngine, ClampsMaterialsToTheEditableRange) {
    const auto asset = slabAsset();
    RelightEngine engine(asset);
    engine.setIrradiance(test::randomMoments(std::uint32_t(asset->samples.size()), 2, 3));
    const Material outside{{1.0, 0.8, 0.6}, {50.0, 0.1, 0.2}, 2.5};
    const std::vector<std::string> warnings = engine.setMaterial(outside);
    EXPECT_EQ(warnings.size(), 2u);  // sigmaA red and eta
    EXPECT_TRUE(asset->range.contains(engine.material()));
    const std::vector<float> clamped(engine.sampleRadiance().begin(), engine.sampleRadiance().end());
    engine.setMaterial(asset->range.clamp(outside, nullptr));
    EXPECT_EQ(test::maxRelative(engine.sampleRadiance(), clamped), 0.0);
}

TEST(RelightEngine, VertexRadianceInterpolatesSamples) {
    const auto asset = slabAsset();
    RelightEngine engine(asset);
    engine.setIrradiance(test::randomMoments(std::uint32_t(asset->samples.size()), 2, 9));
    const std::span<const float> l = engine.sampleRadiance();
    const std::size_t n = asset->samples.size();
    ASSERT_EQ(engine.vertexRadiance().size(), 3 * n);
    for (std::size_t v = 0; v < n; ++v)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(engine.vertexRadiance()[3 * v + c], 0.25f * l[3 * v + c] + 0.75f * l[3 * ((v + 1) % n) + c],
                        1e-6f * l[3 * v + c]);
}

TEST(RelightEngine, LossyTransferStaysCloseToLossless) {
    const auto lossless = slabAsset(), lossy = slabAsset(0.1, 0.99);
    std::size_t kept = 0;
    for (const SparseMatrix& m : lossy->transfer.perBasis) kept += m.nonZeros();
    const IrradianceMoments moments = test::randomMoments(std::uint32_t(lossless->samples.size()), 2, 21);
    RelightEngine a(lossless), b(lossy);
    a.setIrradiance(moments);
    b.setIrradiance(moments);
    const double error = test::relativeRmse(b.sampleRadiance(), a.sampleRadiance());
    std::printf("[ lossy    ] keep 10%% / 99%% energy: %zu of %zu entries, relative RMSE %.4f\n", kept,
                lossless->samples.size() * lossless->samples.size() * lossless->transfer.perBasis.size(), error);
    EXPECT_LT(error, 0.03);
    EXPECT_GT(error, 0.0);
}

TEST(RelightEngine, RejectsMismatchedInput) {
    auto asset = slabAsset();
    RelightEngine engine(asset);
    EXPECT_THROW(engine.setIrradiance(IrradianceMoments(7, 2)), Error);
    EXPECT_THROW(engine.setIrradiance(IrradianceMoments(std::uint32_t(asset->samples.size()), 4)), Error);
    auto broken = std::make_shared<TranslucentAsset>(*asset);
    broken->transfer.perBasis.pop_back();
    EXPECT_THROW(RelightEngine{broken}, Error);
}

// E >= 0 and L >= 0 (docs/ARCHITECTURE.md#nonnegative-radiance): negatives become zero,
// the rest is untouched, and what was zeroed is reported against the highest value.
TEST(ZeroNegatives, ZeroesOnlyTheNegativesAndReportsTheDeepest) {
    std::vector<float> values = {0.5f, -0.002f, 2.0f, 0.0f, -0.01f, 1e-9f};
    const RelightEngine::NegativeNoise noise = zeroNegatives(values);
    EXPECT_EQ(values, (std::vector<float>{0.5f, 0.0f, 2.0f, 0.0f, 0.0f, 1e-9f}));
    EXPECT_EQ(noise.values, 2u);
    EXPECT_DOUBLE_EQ(noise.deepest, double(-0.01f) / 2.0);
    std::vector<float> none = {0.0f, 3.0f};
    EXPECT_EQ(zeroNegatives(none).values, 0u);
    EXPECT_EQ(zeroNegatives(none).deepest, 0.0);
}

// Over several of the pass's tasks and a tail that is not whole vectors, against a plain
// loop over the same values.
TEST(ZeroNegatives, CountsEveryNegativeOfALongArray) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> uniform(-0.2f, 1.0f);
    std::vector<float> values(3 * 32768 + 7);
    for (float& v : values) v = uniform(rng);
    values.back() = -0.5f;  // the deepest, in the tail
    values[40000] = 3.0f;   // the highest, in the second task
    std::uint64_t negatives = 0;
    std::vector<float> expected = values;
    for (float& v : expected) negatives += v < 0.0f, v = std::max(v, 0.0f);
    const RelightEngine::NegativeNoise noise = zeroNegatives(values);
    EXPECT_EQ(values, expected);
    EXPECT_EQ(noise.values, negatives);
    EXPECT_DOUBLE_EQ(noise.deepest, -0.5 / 3.0);
}

}  // namespace
}  // namespace opal
