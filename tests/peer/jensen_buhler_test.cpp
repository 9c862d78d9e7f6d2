#include "bench/jensen_buhler.h"

#include "delegate/relight/reference_gather.h"
#include "schema/error.h"
#include "schema/scatter/dipole.h"
#include "../relight/synthetic_asset.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace opal {
namespace {

using bench::JensenBuhlerOctree;

// A cube-sphere of 6 x 32 x 32 samples, radius 10 mm (samples about 0.45 mm apart, their areas
// varying 5x between face centres and corners), lit by a point light at its side: E falls
// off across the lit half and is a dim ambient on the far one.
TranslucentAsset litSphere(std::vector<float>& irradiance) {
    TranslucentAsset asset;
    asset.unitsPerMm = 0.5;  // 2 mm per scene unit: the octree must work in mm
    test::makeCubeSphere(asset, 5, 5.0f);
    const Imath::V3f light(9.0f, 4.0f, 2.0f);
    irradiance.clear();
    for (const SurfaceSample& s : asset.samples) {
        const Imath::V3f toLight = light - s.position;
        const float cosine = std::max(0.0f, s.normal.dot(toLight.normalized()));
        const float direct = 60.0f * cosine / toLight.length2();
        for (float tint : {1.0f, 0.8f, 0.5f}) irradiance.push_back(tint * direct + 0.05f);
    }
    return asset;
}

// Every fifth sample: outputs over the whole sphere, at a fifth of the gathers' cost.
std::vector<std::uint32_t> everyFifth(const TranslucentAsset& asset) {
    std::vector<std::uint32_t> outputs;
    for (std::uint32_t i = 0; i < asset.samples.size(); i += 5) outputs.push_back(i);
    return outputs;
}

const Material kMarble{{2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}, 1.5};  // long paths: far field matters
const Material kSkin{{0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3};

// The lit sphere with its octree built and its irradiance set.
struct LitSphere {
    std::vector<float> e;
    TranslucentAsset asset = litSphere(e);
    JensenBuhlerOctree octree{asset};

    LitSphere() { octree.setIrradiance(e); }
};

TEST(JensenBuhler, MaxErrorZeroIsTheExactGather) {
    const LitSphere lit;
    const auto& [e, asset, octree] = lit;
    for (const Material& m : {kMarble, kSkin}) {
        const JensenBuhlerOctree::Result peer = octree.radiance(m, 0.0, everyFifth(asset));
        const std::vector<float> exact = referenceGather(asset, m, e, everyFifth(asset));
        ASSERT_EQ(peer.radiance.size(), exact.size());
        for (std::size_t k = 0; k < exact.size(); ++k) ASSERT_NEAR(peer.radiance[k], exact[k], 2e-6 * exact[k]) << k;
        EXPECT_DOUBLE_EQ(peer.interactionsPerOutput, double(asset.samples.size() - 1));
    }
}

TEST(JensenBuhler, ConvergesToTheExactGatherAsMaxErrorShrinks) {
    const LitSphere lit;
    const auto& [e, asset, octree] = lit;
    for (const Material& m : {kMarble, kSkin}) {
        const std::vector<float> exact = referenceGather(asset, m, e, everyFifth(asset));
        double previous = std::numeric_limits<double>::infinity();
        for (double maxError : {0.5, 0.05, 0.01}) {
            const JensenBuhlerOctree::Result peer = octree.radiance(m, maxError, everyFifth(asset));
            const double error = test::relativeRmse(peer.radiance, exact);
            std::printf("[ peer     ] eta %.1f maxError %.2f: relative RMSE %.2e, %.0f of %zu interactions per output\n",
                        m.eta, maxError, error, peer.interactionsPerOutput, asset.samples.size() - 1);
            EXPECT_LT(error, previous) << "maxError " << maxError;
            // The hierarchy at work: far fewer dipole evaluations than samples.
            if (maxError >= 0.05) {
                EXPECT_LT(peer.interactionsPerOutput, double(asset.samples.size()) / 4.0);
            }
            previous = error;
        }
        EXPECT_LT(previous, 1e-3);
    }
}

// Twelve samples within 1 mm, of unequal areas and colours, seen from a sample 8 mm away: the
// octree's first split separates the two, and the far sample takes the cluster's node whole,
// as one source of flux sum_i A_i E_i at the flux-weighted mean position (weights A_i Y(E_i)).
TEST(JensenBuhler, AFarNodeIsItsFluxAtItsFluxCentroid) {
    TranslucentAsset asset;
    std::vector<float> e;
    double flux[3] = {0, 0, 0}, weight = 0.0;
    Imath::V3d centroid(0.0);
    for (int i = 0; i < 12; ++i) {
        const Imath::V3f p(float(i % 3) / 2.0f, float((i / 3) % 2), float(i % 4) / 3.0f);
        const float area = 0.005f * float(1 + i);
        asset.samples.push_back({p, {0, 1, 0}, area});
        const float rgb[3] = {float(i * i), 1.0f + float(i % 5), 12.0f - float(i)};
        const double y = 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
        for (int c = 0; c < 3; ++c) {
            e.push_back(rgb[c]);
            flux[c] += double(area) * rgb[c];
        }
        weight += double(area) * y;
        centroid += Imath::V3d(p) * (double(area) * y);
    }
    centroid /= weight;
    const Imath::V3d far(8.0, 3.0, 3.0);  // the root cell splits at (4, 1.5, 1.5)
    asset.samples.push_back({Imath::V3f(far), {0, 1, 0}, 0.01f});
    for (int c = 0; c < 3; ++c) e.push_back(0.0f);  // no self term

    JensenBuhlerOctree octree(asset);
    octree.setIrradiance(e);
    const std::uint32_t output[] = {12};
    const JensenBuhlerOctree::Result peer = octree.radiance(kSkin, 0.05, output);
    EXPECT_EQ(peer.interactionsPerOutput, 1.0);
    const double r = (far - centroid).length();
    for (int c = 0; c < 3; ++c) {
        const double expected = dipoleProfile(r, kSkin.channel(c)) * flux[c] / std::numbers::pi;
        EXPECT_NEAR(peer.radiance[c], expected, 1e-6 * expected) << "channel " << c;
    }
}

TEST(JensenBuhler, OutputsAreTheSamplesAsked) {
    const LitSphere lit;
    const auto& [e, asset, octree] = lit;
    const std::vector<float> all = octree.radiance(kSkin, 0.05).radiance;
    const std::uint32_t some[] = {7, 3000, 2};
    const std::vector<float> few = octree.radiance(kSkin, 0.05, some).radiance;
    ASSERT_EQ(few.size(), 9u);
    for (std::size_t j = 0; j < 3; ++j)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(few[3 * j + c], all[3 * some[j] + c]);
}

TEST(JensenBuhler, CoincidentSamplesShareALeaf) {
    // 40 samples at one point and one apart: splitting stops at the depth limit.
    TranslucentAsset asset;
    asset.samples.assign(40, SurfaceSample{{1, 2, 3}, {0, 1, 0}, 0.01f});
    asset.samples.push_back({{4, 2, 3}, {0, 1, 0}, 0.01f});
    const std::vector<float> e(3 * asset.samples.size(), 1.0f);
    JensenBuhlerOctree octree(asset);
    octree.setIrradiance(e);
    const std::vector<float> peer = octree.radiance(kSkin, 0.0).radiance;
    const std::vector<float> exact = referenceGather(asset, kSkin, e);
    for (std::size_t k = 0; k < exact.size(); ++k) EXPECT_NEAR(peer[k], exact[k], 2e-6 * exact[k]);
}

TEST(JensenBuhler, RefusesBadInput) {
    std::vector<float> e;
    const TranslucentAsset asset = litSphere(e);
    JensenBuhlerOctree octree(asset);
    EXPECT_THROW(octree.radiance(kSkin), Error);  // no irradiance yet
    EXPECT_THROW(octree.setIrradiance(std::span(e).first(e.size() - 1)), Error);
    octree.setIrradiance(e);
    EXPECT_THROW(octree.radiance(kSkin, -0.1), Error);
    EXPECT_THROW(octree.radiance(kSkin, std::nan("")), Error);
    EXPECT_THROW(octree.radiance(Material{{1, 1, 1}, {0.1, 0.1, 0.1}, 4.0}), Error);
    const std::uint32_t outOfRange[] = {std::uint32_t(asset.samples.size())};
    EXPECT_THROW(octree.radiance(kSkin, 0.05, outOfRange), Error);
    EXPECT_THROW(JensenBuhlerOctree(TranslucentAsset{}), Error);
}

}  // namespace
}  // namespace opal
