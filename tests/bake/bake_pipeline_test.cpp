// The bake pipeline end to end (bake/bake_pipeline.h), checked against truths computed
// here: the exact transfer gather in double precision, the limit-surface area of a
// further-refined mesh, the enclosed volume by the divergence theorem, and the written
// files read back through the schema's validating reader.
#include "bake/bake_pipeline.h"
#include "bake/face_orientation.h"

#include "bake/mesh_validation.h"
#include "bake/procedural_mesh.h"
#include "bake/subdivision.h"
#include "bake/transfer_builder.h"
#include "schema/asset/asset_layer.h"
#include "schema/asset/bake_id.h"
#include "schema/asset/normal_harmonics.h"
#include "schema/asset/transfer_apply.h"
#include "schema/usd/usda_reader.h"
#include "tests/bake/bake_test_support.h"
#include "tests/bake/test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>
#include <numeric>
#include <random>
#include <sstream>

namespace opal {
namespace {

// ---- truths -------------------------------------------------------------------------

// The exact gather y_k(o) = sum_i b_k(|x_o - x_i|) A_i E_i for every output o, in double.
// b_k comes from BasisLookup, the table the builder evaluates: it *defines* T_k, so with
// nothing dropped (keep = energy = 1) the compressed transfer must reproduce this sum up
// to float rounding alone. (ProfileBasis::evaluate interpolates linearly in r, the table
// linearly in sqrt(r); BasisLookupFollowsTheFittedBasis bounds that difference, which is
// far above 1e-5 and would hide a compression error of the same size.)
std::vector<std::vector<double>> exactGather(const TranslucentAsset& asset, const std::vector<float>& irradiance) {
    const BasisLookup lookup(asset.basis);
    const int K = lookup.K();
    const std::size_t n = asset.samples.size();
    const double toMm = 1.0 / asset.unitsPerMm;
    std::vector<std::vector<double>> y(std::size_t(K), std::vector<double>(n, 0.0));
    std::vector<float> b(static_cast<std::size_t>(K));
    for (std::size_t o = 0; o < n; ++o) {
        const Imath::V3d xo(asset.samples[o].position);
        for (std::size_t i = 0; i < n; ++i) {
            if (i == o) continue;
            const double r = (Imath::V3d(asset.samples[i].position) - xo).length() * toMm;
            lookup.evaluate(float(r), b.data());
            const double weight = double(asset.samples[i].area) * toMm * toMm * irradiance[i];
            for (int k = 0; k < K; ++k) y[std::size_t(k)][o] += double(b[std::size_t(k)]) * weight;
        }
        // The diagonal is 0: the relighter adds the self term (SelfTerm::AtRunTime).
    }
    return y;
}

std::vector<double> unitVector(int K, int k) {
    std::vector<double> s(std::size_t(K), 0.0);
    s[std::size_t(k)] = 1.0;
    return s;
}

// sqrt(sum_k ||applyTransfer(e_k) - exact_k||^2 / sum_k ||exact_k||^2).
double relativeError(const CompressedTransfer& transfer, const TranslucentAsset& asset,
                     const std::vector<float>& irradiance, const std::vector<std::vector<double>>& exact) {
    double errorSq = 0.0, exactSq = 0.0;
    const int K = asset.basis.K();
    for (int k = 0; k < K; ++k) {
        const std::vector<float> y = applyTransfer(transfer, asset.layout, unitVector(K, k), irradiance, asset.samples);
        for (std::size_t o = 0; o < y.size(); ++o) {
            const double d = double(y[o]) - exact[std::size_t(k)][o];
            errorSq += d * d;
            exactSq += exact[std::size_t(k)][o] * exact[std::size_t(k)][o];
        }
    }
    return std::sqrt(errorSq / exactSq);
}

std::vector<float> randomIrradiance(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::vector<float> e(n);
    for (float& v : e) v = uniform(random);
    return e;
}

// Signed volume of a closed polygon mesh (bake/face_orientation.h, tested on its own).
double renderMeshVolume(const RenderMesh& mesh) {
    return opal::enclosedVolume(mesh.points, mesh.faceVertexCounts, mesh.faceVertexIndices);
}

// The limit surface refined `extra` levels beyond the render mesh: its polygon area is
// within float noise of the true limit-surface area.
RenderMesh refinedFurther(ControlMesh control, SubdivisionScheme scheme, int level) {
    validateAndRepair(control);
    return subdivide(control, {scheme, level});
}

template <class T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

bool sameBits(const std::vector<Imath::V3f>& a, const std::vector<Imath::V3f>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Imath::V3f)) == 0);
}

bool sameSamples(const std::vector<SurfaceSample>& a, const std::vector<SurfaceSample>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const auto bits = [](const SurfaceSample& s) {
            return std::array<std::uint32_t, 7>{std::bit_cast<std::uint32_t>(s.position.x),
                                                std::bit_cast<std::uint32_t>(s.position.y),
                                                std::bit_cast<std::uint32_t>(s.position.z),
                                                std::bit_cast<std::uint32_t>(s.normal.x),
                                                std::bit_cast<std::uint32_t>(s.normal.y),
                                                std::bit_cast<std::uint32_t>(s.normal.z),
                                                std::bit_cast<std::uint32_t>(s.area)};
        };
        if (bits(a[i]) != bits(b[i])) return false;
    }
    return true;
}

// ---- a small exact bake, shared -----------------------------------------------------

// The built-in candle, 512 samples (2 charts of 16 x 16), level 1, with nothing dropped
// by either compression step. 0.5 scene units per mm, so a missing or doubled unit
// conversion shows up in the gather.
class ExactCandle : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        BakeOptions options;
        options.input = "builtin:candle";
        options.level = 1;
        options.samples = 512;
        options.unitsPerMm = 0.5;
        options.transfer.keepFraction = 1.0;
        options.transfer.energyFraction = 1.0;
        options.visibility.cubeFaceSize = 8;
        options.visibility.terms = 32;
        report_ = new BakeReport;
        try {
            asset_ = new TranslucentAsset(bakeAsset(options, nullptr, CancelToken{}, report_));
        } catch (const std::exception& e) {
            setupError_ = e.what();
            return;
        }
        irradiance_ = new std::vector<float>(randomIrradiance(asset_->samples.size(), 20240611));
        exact_ = new std::vector<std::vector<double>>(exactGather(*asset_, *irradiance_));
    }
    void SetUp() override { ASSERT_NE(asset_, nullptr) << "the bake failed: " << setupError_; }
    static void TearDownTestSuite() {
        delete exact_;
        delete irradiance_;
        delete asset_;
        delete report_;
        asset_ = nullptr;
    }

    static TranslucentAsset* asset_;
    static BakeReport* report_;
    static std::vector<float>* irradiance_;
    static std::vector<std::vector<double>>* exact_;
    static inline std::string setupError_;
};

TranslucentAsset* ExactCandle::asset_ = nullptr;
BakeReport* ExactCandle::report_ = nullptr;
std::vector<float>* ExactCandle::irradiance_ = nullptr;
std::vector<std::vector<double>>* ExactCandle::exact_ = nullptr;

TEST_F(ExactCandle, KeepingEverythingReproducesTheExactGatherPerBasisFunction) {
    const TranslucentAsset& a = *asset_;
    ASSERT_EQ(a.samples.size(), 512u);
    ASSERT_EQ(a.layout.charts, 2u);
    ASSERT_EQ(a.layout.size(), 16u);
    const int K = a.basis.K();
    ASSERT_EQ(K, BakeOptions{}.basisCount);
    ASSERT_EQ(a.transfer.perBasis.size(), std::size_t(K));
    EXPECT_EQ(a.transfer.keepFraction, 1.0);
    EXPECT_EQ(a.transfer.energyFraction, 1.0);
    EXPECT_NEAR(report_->transfer.energyKept, 1.0, 1e-12);
    EXPECT_EQ(a.transfer.selfTerm, SelfTerm::AtRunTime);  // the diagonal is 0 in exactGather

    for (int k = 0; k < K; ++k) {
        const std::vector<float> y = applyTransfer(a.transfer, a.layout, unitVector(K, k), *irradiance_, a.samples);
        const std::vector<double>& exact = (*exact_)[std::size_t(k)];
        double maxExact = 0.0, maxError = 0.0, errorSq = 0.0, exactSq = 0.0;
        for (std::size_t o = 0; o < y.size(); ++o) {
            maxExact = std::max(maxExact, std::abs(exact[o]));
            maxError = std::max(maxError, std::abs(double(y[o]) - exact[o]));
            errorSq += (double(y[o]) - exact[o]) * (double(y[o]) - exact[o]);
            exactSq += exact[o] * exact[o];
        }
        ASSERT_GT(maxExact, 0.0) << "k = " << k;
        // Max-norm relative error: stricter than the RMS for outputs where b_k cancels.
        EXPECT_LE(maxError / maxExact, 1e-5) << "k = " << k << ", RMS rel. " << std::sqrt(errorSq / exactSq);
    }
    // The report's own measure (a point light, the default material) agrees.
    EXPECT_LE(report_->transferRelRmse, 1e-5);
}

// The harmonic transfer is T_k f_q with nothing dropped: the exact gather (double sums over
// every pair) of each function of the bake's set (36: the normal harmonics times the
// position in the samples' frame) as the light.
TEST_F(ExactCandle, HarmonicTransferIsTheExactGatherOfEachHarmonic) {
    const TranslucentAsset& a = *asset_;
    const std::size_t n = a.samples.size(), K = std::size_t(a.basis.K());
    const HarmonicSet& set = a.transfer.harmonicSet;
    ASSERT_EQ(set.count, kMaxHarmonics);
    const HarmonicSet expected = harmonicSetFor(a.samples);
    EXPECT_EQ(set.centre, expected.centre);
    EXPECT_EQ(set.inverseScale, expected.inverseScale);
    const std::size_t Q = set.count;
    ASSERT_EQ(a.transfer.harmonics.size(), n * K * Q);
    std::vector<float> f(Q);
    for (std::size_t q = 0; q < Q; ++q) {
        std::vector<float> light(n);
        for (std::size_t i = 0; i < n; ++i) {
            harmonicValues(set, a.samples[i], f);
            light[i] = f[q];
        }
        const std::vector<std::vector<double>> exact = exactGather(a, light);
        for (std::size_t k = 0; k < K; ++k) {
            double peak = 0.0, worst = 0.0;
            for (std::size_t o = 0; o < n; ++o) {
                peak = std::max(peak, std::abs(exact[k][o]));
                worst = std::max(worst, std::abs(a.transfer.harmonics[(o * K + k) * Q + q] - exact[k][o]));
            }
            ASSERT_GT(peak, 0.0) << "k = " << k << ", q = " << q;
            EXPECT_LE(worst, 1e-5 * peak) << "k = " << k << ", q = " << q;
        }
    }
}

TEST_F(ExactCandle, BasisLookupFollowsTheFittedBasis) {
    // The exact gather above uses BasisLookup; here the table is held to ProfileBasis::
    // evaluate at the table's own midpoints (the worst place for linear interpolation).
    const ProfileBasis& basis = asset_->basis;
    const BasisLookup lookup(basis);
    std::vector<float> b(std::size_t(basis.K()));
    for (int k = 0; k < basis.K(); ++k) {
        double peak = 0.0, worst = 0.0;
        for (double r : basis.radii()) peak = std::max(peak, std::abs(basis.evaluate(k, r)));
        for (int i = 0; i < 4096; ++i) {
            const double u = (i + 0.5) / 4096.0;
            const double r = basis.rMax() * u * u;
            lookup.evaluate(float(r), b.data());
            worst = std::max(worst, std::abs(double(b[std::size_t(k)]) - basis.evaluate(k, r)));
        }
        EXPECT_LE(worst, 2e-3 * peak) << "k = " << k;
    }
    lookup.evaluate(float(basis.rMax()) * 1.01f, b.data());
    for (float v : b) EXPECT_EQ(v, 0.0f);
}

TEST_F(ExactCandle, ErrorGrowsAsEitherStepKeepsLess) {
    const TranslucentAsset& a = *asset_;
    const double exactError = relativeError(a.transfer, a, *irradiance_, *exact_);
    EXPECT_LE(exactError, 1e-5);

    // minPerRow 1: the fraction alone sets step 1's budget (the floor is checked below).
    const auto build = [&](double keep, double energy, TransferStats* stats, std::uint32_t minPerRow = 1) {
        return buildTransfer(a.samples, a.layout, a.unitsPerMm, a.basis, TransferSettings{keep, energy, minPerRow},
                             nullptr, CancelToken{}, stats);
    };
    const std::size_t n = a.samples.size();
    const std::uint64_t K = std::uint64_t(a.basis.K());

    // Step 1 alone (energy 1): the error grows as fewer Haar coefficients are kept.
    double previous = exactError;
    for (double keep : {0.3, 0.1, 0.03}) {
        TransferStats stats;
        const CompressedTransfer t = build(keep, 1.0, &stats);
        const double error = relativeError(t, a, *irradiance_, *exact_);
        EXPECT_GT(error, previous) << "keep " << keep;
        previous = error;
        EXPECT_EQ(stats.rawBytes, std::uint64_t(n) * n * K * 4);
        // keep x N coefficients per row of each T_k on average over k (split by eigenvalue,
        // each rounded up): index + value per entry.
        EXPECT_GE(stats.step1Bytes, std::uint64_t(std::ceil(keep * double(n) * double(K))) * n * 8);
        EXPECT_LE(stats.step1Bytes, (std::uint64_t(std::ceil(keep * double(n) * double(K))) + K) * n * 8);
        EXPECT_NEAR(stats.energyKept, 1.0, 1e-12);
    }
    EXPECT_GT(previous, 1e-3) << "keeping 3% of the Haar coefficients should cost visible accuracy";

    // The floor: a fraction below minPerRow / N keeps minPerRow per row, the same transfer
    // as asking for that fraction.
    {
        const std::uint32_t floor = std::uint32_t(n / 8);
        TransferStats floored, fraction;
        const CompressedTransfer a1 = build(0.001, 1.0, &floored, floor);
        const CompressedTransfer a2 = build(double(floor) / double(n), 1.0, &fraction);
        EXPECT_TRUE(floored.step1Floor);
        EXPECT_FALSE(fraction.step1Floor);
        EXPECT_EQ(floored.step1Bytes, fraction.step1Bytes);
        EXPECT_NEAR(floored.step1PerRow, double(floor), double(K));  // each k's share rounded up
        for (std::size_t k = 0; k < a1.perBasis.size(); ++k) EXPECT_EQ(a1.perBasis[k].values, a2.perBasis[k].values);
    }

    // Step 2 alone (keep 1): the error grows as less 9/7 energy is kept, and the energy
    // actually kept reaches the target and falls with it.
    previous = exactError;
    double previousEnergy = 1.0;
    std::uint64_t previousNonZeros = std::numeric_limits<std::uint64_t>::max();
    for (double energy : {0.999, 0.99, 0.97}) {
        TransferStats stats;
        const CompressedTransfer t = build(1.0, energy, &stats);
        const double error = relativeError(t, a, *irradiance_, *exact_);
        EXPECT_GT(error, previous) << "energy " << energy;
        previous = error;
        EXPECT_GE(stats.energyKept, energy);
        EXPECT_LT(stats.energyKept, previousEnergy);
        previousEnergy = stats.energyKept;
        std::uint64_t nonZeros = 0;
        for (const SparseMatrix& m : t.perBasis) nonZeros += m.nonZeros();
        EXPECT_EQ(stats.step2NonZeros, nonZeros);
        EXPECT_EQ(stats.step2Bytes, nonZeros * 8);
        EXPECT_LT(nonZeros, previousNonZeros);
        previousNonZeros = nonZeros;
    }
}

// ---- samples and parameterization ---------------------------------------------------

// `outwardAt(p)`: a direction a correct normal at p makes an acute angle with.
void expectSamplesCoverTheLimitSurface(const TranslucentAsset& a, double limitArea, double limitVolume,
                                       const std::function<Imath::V3f(const Imath::V3f&)>& outwardAt) {
    double areaSum = 0.0;
    double volume = 0.0;  // (1/3) sum A n.x = enclosed volume for outward normals
    std::size_t inward = 0;
    for (const SurfaceSample& s : a.samples) {
        areaSum += s.area;
        EXPECT_NEAR(s.normal.length(), 1.0f, 1e-5f);
        volume += double(s.area) * double(s.normal.dot(s.position)) / 3.0;
        if (s.normal.dot(outwardAt(s.position)) <= 0.0f) ++inward;
    }
    EXPECT_NEAR(areaSum, limitArea, 0.01 * limitArea);
    EXPECT_NEAR(volume, limitVolume, 0.03 * limitVolume);
    EXPECT_EQ(inward, 0u) << "samples whose normal faces inward";
}

// For a shape star-shaped about `centre`, away from it is outward.
std::function<Imath::V3f(const Imath::V3f&)> awayFrom(const Imath::V3f& centre) {
    return [centre](const Imath::V3f& p) { return p - centre; };
}

// The outward normal of the nearest vertex of a fine mesh (a surface with concave parts,
// such as the candle's pool and the inner wall of its rim, is not star-shaped).
std::function<Imath::V3f(const Imath::V3f&)> nearestVertexNormal(const RenderMesh& fine) {
    return [&fine](const Imath::V3f& p) {
        std::size_t nearest = 0;
        for (std::size_t v = 1; v < fine.points.size(); ++v)
            if ((fine.points[v] - p).length2() < (fine.points[nearest] - p).length2()) nearest = v;
        return fine.normals[nearest];
    };
}

// Grid neighbours in a chart are surface neighbours: the mean distance between cells
// that share an edge, in units of the sample spacing sqrt(A / N), and the same for a
// shuffled order.
std::pair<double, double> gridNeighbourDistance(const TranslucentAsset& a) {
    const ChartLayout& layout = a.layout;
    double area = 0.0;
    for (const SurfaceSample& s : a.samples) area += s.area;
    const double spacing = std::sqrt(area / double(a.samples.size()));
    std::vector<std::size_t> shuffled(a.samples.size());
    std::iota(shuffled.begin(), shuffled.end(), 0);
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937_64(7));
    double sum = 0.0, shuffledSum = 0.0;
    std::size_t pairs = 0;
    const std::size_t size = layout.size();
    for (std::size_t chart = 0; chart < layout.charts; ++chart)
        for (std::size_t v = 0; v < size; ++v)
            for (std::size_t u = 0; u < size; ++u) {
                const std::size_t cell = chart * size * size + v * size + u;
                for (std::size_t other : {u + 1 < size ? cell + 1 : cell, v + 1 < size ? cell + size : cell}) {
                    if (other == cell) continue;
                    sum += (a.samples[cell].position - a.samples[other].position).length();
                    shuffledSum += (a.samples[shuffled[cell]].position - a.samples[shuffled[other]].position).length();
                    ++pairs;
                }
            }
    return {sum / double(pairs) / spacing, shuffledSum / double(pairs) / spacing};
}

TEST_F(ExactCandle, SamplesCoverTheCandleLimitSurfaceWithOutwardNormals) {
    const RenderMesh fine = refinedFurther(makeCandle(), SubdivisionScheme::CatmullClark, 4);
    const double limitArea = test::renderMeshArea(fine);
    const double limitVolume = renderMeshVolume(fine);
    ASSERT_GT(limitVolume, 0.0);
    // A 40 mm x 80 mm pillar: the limit surface is a little smaller than the cage.
    EXPECT_NEAR(limitArea, 2 * M_PI * 20 * 20 + 2 * M_PI * 20 * 78, 0.1 * limitArea);
    expectSamplesCoverTheLimitSurface(*asset_, limitArea, limitVolume, nearestVertexNormal(fine));
    EXPECT_EQ(report_->samples, 512u);
    EXPECT_EQ(report_->charts, 2u);
    EXPECT_EQ(report_->grid, 16u);
    EXPECT_EQ(report_->renderVertices, asset_->mesh.points.size());

    const auto [neighbour, shuffled] = gridNeighbourDistance(*asset_);
    EXPECT_LT(neighbour, 3.0) << "grid neighbours should be a couple of sample spacings apart";
    EXPECT_LT(neighbour, 0.3 * shuffled) << "random pairs are " << shuffled << " spacings apart";
}

// A bake of a mesh file at a fixed level with a small environment transfer.
BakeOptions fileBakeOptions(const std::filesystem::path& input, std::uint32_t level, std::uint64_t samples,
                            std::uint32_t envTerms) {
    BakeOptions options;
    options.input = input.string();
    options.level = level;
    options.samples = samples;
    options.visibility.cubeFaceSize = 8;
    options.visibility.terms = envTerms;
    return options;
}

TEST(BakePipeline, SphereSamplesAreaNormalsAndChartsAgainstClosedForms) {
    // An icosphere of radius 25 mm read from an OBJ (Loop subdivision, the importer path).
    const test::ScratchDir dir;
    const ControlMesh control = test::icosphere(2, 25.0f);
    test::writeText(dir / "sphere.obj", test::objText(control));
    const BakeOptions options = fileBakeOptions(dir / "sphere.obj", 1, 1024, 32);
    BakeReport report;
    const TranslucentAsset a = bakeAsset(options, nullptr, CancelToken{}, &report);
    EXPECT_EQ(a.bake.scheme, "loop");
    ASSERT_EQ(a.samples.size(), 1024u);
    EXPECT_EQ(a.layout.charts, 1u);
    EXPECT_EQ(a.layout.size(), 32u);

    const RenderMesh fine = refinedFurther(control, SubdivisionScheme::Loop, 4);
    const double limitArea = test::renderMeshArea(fine);
    // Loop shrinks the icosphere a little: the limit is a near-sphere inside radius 25.
    EXPECT_LT(limitArea, 4 * M_PI * 25 * 25);
    EXPECT_GT(limitArea, 0.95 * 4 * M_PI * 25 * 25);
    expectSamplesCoverTheLimitSurface(a, limitArea, renderMeshVolume(fine), awayFrom(Imath::V3f(0.0f)));
    for (const SurfaceSample& s : a.samples) EXPECT_GT(s.normal.dot(s.position.normalized()), 0.99f);

    const auto [neighbour, shuffled] = gridNeighbourDistance(a);
    EXPECT_LT(neighbour, 3.0);
    EXPECT_LT(neighbour, 0.3 * shuffled) << "random pairs are " << shuffled << " spacings apart";
}

TEST(BakePipeline, AMeshTooSmallForTheBasisIsRefusedNamingTheAssetAndItsSize) {
    // Radius 0.01 mm: a diagonal of 0.035 mm, shorter than the profiles' own scale, so the
    // basis cannot hold K = 16 functions (an object authored in metres, baked as mm).
    const test::ScratchDir dir;
    test::writeText(dir / "tiny.obj", test::objText(test::icosphere(1, 0.01f)));
    const BakeOptions options = fileBakeOptions(dir / "tiny.obj", 0, 256, 16);
    try {
        bakeAsset(options, nullptr, CancelToken{}, nullptr);
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        for (const char* part : {"asset 'tiny'", "tiny.obj", "bounding-box diagonal 0.03", "--units-per-mm 1",
                                 "independent components", "K = 16"})
            EXPECT_NE(what.find(part), std::string::npos) << what << " lacks " << part;
    }
}

// ---- the written asset --------------------------------------------------------------

// Found with find, not std::regex: libstdc++'s regex recurses once per character matched
// and overflows the stack on an array of some 100,000 characters.
std::vector<std::int32_t> intArrayInText(const std::string& usda, const std::string& name) {
    const std::string opening = "int[] " + name + " = [";
    const std::size_t begin = usda.find(opening);
    if (begin == std::string::npos) return {};
    const std::size_t first = begin + opening.size(), end = usda.find(']', first);
    if (end == std::string::npos) return {};
    std::vector<std::int32_t> values;
    std::string text = usda.substr(first, end - first);
    std::replace(text.begin(), text.end(), ',', ' ');
    std::istringstream in(text);
    for (std::int32_t v; in >> v;) values.push_back(v);
    return values;
}

TEST(BakePipeline, WrittenAssetReadsBackBitExact) {
    const test::ScratchDir dir;
    BakeOptions options;
    options.input = "builtin:candle";
    options.level = 1;
    options.samples = 1024;
    options.material = "skin1";
    BakeReport report;
    const TranslucentAsset a = bakeAsset(options, nullptr, CancelToken{}, &report);
    writeBakedAsset(dir / "candle", a, &report);
    ASSERT_TRUE(a.bake.identifier.has_value());
    const std::string sidecar = "candle." + formatBakeId(*a.bake.identifier) + ".opal";
    EXPECT_EQ(dir.list(), (std::vector<std::string>{sidecar, "candle.usda"}));
    EXPECT_EQ(report.sidecarFile, dir / sidecar);
    EXPECT_EQ(report.sidecarBytes, std::filesystem::file_size(dir / sidecar));

    // The layer as text: the applied schema and the render mesh as authored.
    const std::string usda = test::readBytes(dir / "candle.usda");
    EXPECT_NE(usda.find("prepend apiSchemas = [\"OpalSubsurfaceAPI\"]"), std::string::npos);
    for (const char* attr : {"opal:eta", "opal:sigmaA", "opal:sigmaSPrime", "opal:unitsPerMm",
                             "opal:range:sigmaSPrime", "opal:range:sigmaA", "opal:range:eta", "opal:basis:K",
                             "opal:basis:eigenvalues", "opal:basis:radii", "opal:basis:weights",
                             "opal:basis:values", "opal:sidecar", "opal:bakeId"})
        EXPECT_NE(usda.find(std::string(attr) + " = "), std::string::npos) << attr;
    EXPECT_TRUE(usda.find("opal:sidecar = @" + sidecar + "@") != std::string::npos ||
                usda.find("opal:sidecar = @./" + sidecar + "@") != std::string::npos)
        << "the sidecar path is the sidecar's name, relative to the layer";
    EXPECT_NE(usda.find("opal:bakeId = \"" + formatBakeId(*a.bake.identifier) + "\""), std::string::npos);
    EXPECT_NE(usda.find("subdivisionScheme = \"none\""), std::string::npos);
    EXPECT_EQ(intArrayInText(usda, "faceVertexCounts"), a.mesh.faceVertexCounts);
    EXPECT_EQ(intArrayInText(usda, "faceVertexIndices"), a.mesh.faceVertexIndices);
    const usda::Layer layer = usda::readUsdaFile(dir / "candle.usda");
    ASSERT_EQ(layer.rootPrims.size(), 1u);
    const usda::Prim& prim = layer.rootPrims.front();
    EXPECT_EQ(prim.typeName, "Mesh");
    EXPECT_EQ(prim.apiSchemas.prepended, std::vector<std::string>{"OpalSubsurfaceAPI"});
    const auto& points = prim.attribute("points").get<usda::types::Point3fArray>();
    ASSERT_EQ(points.size(), a.mesh.points.size());
    for (std::size_t v = 0; v < points.size(); ++v)
        ASSERT_TRUE(points[v][0] == a.mesh.points[v].x && points[v][1] == a.mesh.points[v].y &&
                    points[v][2] == a.mesh.points[v].z)
            << "point " << v;

    // The validating reader accepts both files, and everything comes back.
    const TranslucentAsset b = readAsset(dir / "candle.usda");
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.unitsPerMm, a.unitsPerMm);
    EXPECT_TRUE(sameBits(b.mesh.points, a.mesh.points));
    EXPECT_TRUE(sameBits(b.mesh.normals, a.mesh.normals));
    EXPECT_EQ(b.mesh.faceVertexCounts, a.mesh.faceVertexCounts);
    EXPECT_EQ(b.mesh.faceVertexIndices, a.mesh.faceVertexIndices);
    EXPECT_EQ(b.layout.charts, a.layout.charts);
    EXPECT_EQ(b.layout.log2Size, a.layout.log2Size);
    EXPECT_TRUE(sameSamples(b.samples, a.samples));
    EXPECT_EQ(b.vertexWeights.offsets, a.vertexWeights.offsets);
    EXPECT_EQ(b.vertexWeights.samples, a.vertexWeights.samples);
    EXPECT_TRUE(sameBits(b.vertexWeights.weights, a.vertexWeights.weights));
    ASSERT_EQ(b.transfer.perBasis.size(), a.transfer.perBasis.size());
    for (std::size_t k = 0; k < a.transfer.perBasis.size(); ++k) {
        const SparseMatrix &x = a.transfer.perBasis[k], &y = b.transfer.perBasis[k];
        EXPECT_EQ(y.rows, x.rows);
        EXPECT_EQ(y.cols, x.cols);
        EXPECT_EQ(y.rowOffsets, x.rowOffsets) << "k = " << k;
        EXPECT_EQ(y.columns, x.columns) << "k = " << k;
        EXPECT_TRUE(sameBits(y.values, x.values)) << "k = " << k;
    }
    EXPECT_EQ(b.transfer.keepFraction, a.transfer.keepFraction);
    EXPECT_EQ(b.transfer.energyFraction, a.transfer.energyFraction);
    ASSERT_EQ(a.transfer.harmonics.size(), a.samples.size() * a.transfer.perBasis.size() * kMaxHarmonics);
    EXPECT_TRUE(sameBits(b.transfer.harmonics, a.transfer.harmonics));
    EXPECT_EQ(b.transfer.harmonicSet.count, a.transfer.harmonicSet.count);
    EXPECT_EQ(b.transfer.harmonicSet.centre, a.transfer.harmonicSet.centre);
    EXPECT_EQ(b.transfer.harmonicSet.inverseScale, a.transfer.harmonicSet.inverseScale);
    EXPECT_EQ(b.environment.cubeFaceSize, a.environment.cubeFaceSize);
    EXPECT_EQ(b.environment.fresnelTerms, a.environment.fresnelTerms);
    EXPECT_EQ(b.environment.offsets, a.environment.offsets);
    EXPECT_EQ(b.environment.indices, a.environment.indices);
    EXPECT_TRUE(sameBits(b.environment.values, a.environment.values));
    EXPECT_FALSE(a.environment.offsets.empty());

    const auto same = [](std::span<const double> x, std::span<const double> y) {
        return std::vector<double>(x.begin(), x.end()) == std::vector<double>(y.begin(), y.end());
    };
    EXPECT_EQ(b.basis.K(), a.basis.K());
    EXPECT_TRUE(same(b.basis.values(), a.basis.values()));
    EXPECT_TRUE(same(b.basis.radii(), a.basis.radii()));
    EXPECT_TRUE(same(b.basis.weights(), a.basis.weights()));
    EXPECT_TRUE(same(b.basis.eigenvalues(), a.basis.eigenvalues()));
    EXPECT_EQ(b.range.sigmaSPrimeMin, a.range.sigmaSPrimeMin);
    EXPECT_EQ(b.range.sigmaAMax, a.range.sigmaAMax);
    EXPECT_EQ(b.range.etaMax, a.range.etaMax);
    // The material is stored as float (opal:eta is a float, the coefficients color3f).
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(b.defaultMaterial.sigmaA[c], double(float(a.defaultMaterial.sigmaA[c])));
        EXPECT_EQ(b.defaultMaterial.sigmaSPrime[c], double(float(a.defaultMaterial.sigmaSPrime[c])));
    }
    EXPECT_EQ(b.defaultMaterial.eta, double(float(a.defaultMaterial.eta)));
    const Material skin1 = *findPreset("skin1");
    EXPECT_NEAR(b.defaultMaterial.sigmaA[0], skin1.sigmaA[0], 1e-6 * skin1.sigmaA[0]);
    EXPECT_EQ(b.bake.source, "builtin:candle");
    EXPECT_EQ(b.bake.scheme, "catmullClark");
    EXPECT_EQ(b.bake.level, 1u);
    EXPECT_EQ(b.bake.seed, a.bake.seed);
    EXPECT_EQ(b.bake.envTerms, a.bake.envTerms);
    EXPECT_EQ(b.bake.identifier, a.bake.identifier);

    // The reported error is the in-memory asset's, and the stored asset gives the same up
    // to the material's rounding to float: a change of about 1e-7 of L, against an error
    // of about 2e-3 of L, so 1e-4 of the error.
    EXPECT_EQ(report.transferRelRmse, measureTransferError(a, options.seed));
    EXPECT_NEAR(measureTransferError(b, options.seed), report.transferRelRmse, 1e-4 * report.transferRelRmse);
    EXPECT_GT(report.transferRelRmse, 0.0);
}

TEST(BakePipeline, RewritingKeepsOnlyTheTwoFiles) {
    // Overwriting an asset replaces both files (the superseded sidecar is removed) and
    // leaves no temporary or lock file behind.
    const test::ScratchDir dir;
    BakeOptions options;
    options.input = "builtin:candle";
    options.level = 0;
    options.samples = 256;
    options.visibility.cubeFaceSize = 8;
    options.visibility.terms = 16;
    const TranslucentAsset a = bakeAsset(options, nullptr, CancelToken{}, nullptr);
    writeBakedAsset(dir / "c", a, nullptr);
    const std::string first = test::sidecarNamedBy(dir / "c.usda");
    EXPECT_EQ(dir.list(), (std::vector<std::string>{first, "c.usda"}));
    options.seed = 2;
    const TranslucentAsset b = bakeAsset(options, nullptr, CancelToken{}, nullptr);
    writeBakedAsset(dir / "c", b, nullptr);
    const std::string second = test::sidecarNamedBy(dir / "c.usda");
    EXPECT_NE(second, first) << "another seed is another bake";
    EXPECT_EQ(dir.list(), (std::vector<std::string>{second, "c.usda"}));
    EXPECT_EQ(readAsset(dir / "c.usda").bake.seed, 2u);
}

// Records the stages a bake begins.
struct StageRecorder final : ProgressSink {
    std::vector<std::string> stages;
    void beginStage(std::string_view name, std::uint64_t) override { stages.emplace_back(name); }
    void advance(std::uint64_t) override {}
    void endStage() override {}
};

TEST(BakePipeline, BadOptionsFailBeforeAnyStageStarts) {
    // A bake of 65,536 samples runs for minutes: an option that a late stage would refuse
    // must be refused before the first stage, with the option named. (256 samples here, so
    // that a regression fails in a second instead of baking.)
    struct Case {
        const char* what;
        void (*edit)(BakeOptions&);
        const char* expected;
    };
    const Case cases[] = {
        {"samples", [](BakeOptions& o) { o.samples = 1000; }, "sample count 1000"},
        {"env-res", [](BakeOptions& o) { o.visibility.cubeFaceSize = 24; }, "--env-res"},
        {"env-terms", [](BakeOptions& o) { o.visibility.terms = 0; }, "--env-terms"},
        {"material", [](BakeOptions& o) { o.material = "jade"; }, "--material"},
        {"units", [](BakeOptions& o) { o.unitsPerMm = 0.0; }, "--units-per-mm"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        BakeOptions options;
        options.input = "builtin:candle";
        options.samples = 256;
        c.edit(options);
        StageRecorder recorder;
        try {
            bakeAsset(options, &recorder, CancelToken{}, nullptr);
            ADD_FAILURE() << "no error";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << e.what();
        }
        EXPECT_TRUE(recorder.stages.empty()) << "began " << recorder.stages.front();
    }
}

TEST(BakePipeline, CancelledBakeThrowsCancelled) {
    std::atomic<bool> flag{true};
    BakeOptions options;
    options.input = "builtin:candle";
    options.samples = 256;
    EXPECT_THROW(bakeAsset(options, nullptr, CancelToken(&flag), nullptr), Cancelled);
}

}  // namespace

// With more environment terms than a sample has nonzero Haar coefficients (a coarse cube
// map), rows are shorter than --env-terms; they used to be padded with index 0, which the
// sidecar writer rightly refused after the whole bake.
TEST(BakePipeline, ShortEnvironmentRowsAreStoredWithoutPadding) {
    const test::ScratchDir dir;
    BakeOptions options;
    options.input = "builtin:candle";
    options.level = 1;
    options.samples = 256;
    options.visibility.cubeFaceSize = 8;
    options.visibility.terms = 200;
    BakeReport report;
    const TranslucentAsset a = bakeAsset(options, nullptr, CancelToken{}, &report);
    const std::size_t rows = a.samples.size() * a.environment.fresnelTerms;
    ASSERT_EQ(a.environment.offsets.size(), rows + 1);
    bool someShort = false;
    for (std::size_t r = 0; r < rows; ++r) {
        const std::uint32_t begin = a.environment.offsets[r], end = a.environment.offsets[r + 1];
        ASSERT_LE(end - begin, 200u);
        someShort = someShort || end - begin < 200u;
        for (std::uint32_t e = begin + 1; e < end; ++e)
            ASSERT_LT(a.environment.indices[e - 1], a.environment.indices[e]) << "row " << r;
    }
    EXPECT_TRUE(someShort) << "an 8x8 cube map has rows with fewer than 200 nonzero coefficients";
    writeBakedAsset(dir / "candle", a, &report);
    const TranslucentAsset back = readAsset(dir / "candle.usda");
    EXPECT_EQ(back.environment.offsets, a.environment.offsets);
    EXPECT_EQ(back.environment.indices, a.environment.indices);
}

}  // namespace opal
