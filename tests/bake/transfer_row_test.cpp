// transferRow against two independent evaluations of T_k[o][i] = b_k(|x_o - x_i|) A_i
// (docs/ARCHITECTURE.md#transfer): a double-precision one on a basis whose functions are linear in
// r (so the lookup table's interpolation is exact up to float rounding), and the per-pair
// float loop the bake used before (Imath length, BasisLookup::evaluate, times A_i), which
// it must reproduce bit for bit.
#include "bake/transfer_row.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace opal {
namespace {

constexpr double kRMax = 40.0;  // mm

// b_k(r) = c_k + d_k r on [0, rMax] (two radii: ProfileBasis interpolates linearly).
double linearBasis(int k, double r) { return r > kRMax ? 0.0 : (1.0 + 0.5 * k) - (0.02 + 0.01 * k) * r * (k % 2 ? 1 : -1); }

ProfileBasis makeLinearBasis(int K) {
    std::vector<double> values;
    for (int k = 0; k < K; ++k) values.insert(values.end(), {linearBasis(k, 0.0), linearBasis(k, kRMax)});
    return ProfileBasis({0.0, kRMax}, {1.0, 1.0}, values, std::vector<double>(K, 1.0), EditableRange::coveringPresets());
}

// A curved basis (exponentials at 64 radii), as fitted profiles look.
ProfileBasis makeCurvedBasis(int K) {
    const int L = 64;
    std::vector<double> radii(L), values;
    for (int l = 0; l < L; ++l) radii[l] = kRMax * std::pow(double(l) / (L - 1), 3.0);
    for (int k = 0; k < K; ++k)
        for (int l = 0; l < L; ++l) values.push_back(std::exp(-radii[l] * (k + 1) / 8.0) * (k % 3 ? 1.0 : -2.0));
    return ProfileBasis(radii, std::vector<double>(L, 1.0), values, std::vector<double>(K, 1.0),
                        EditableRange::coveringPresets());
}

// Samples in scene units (unitsPerMm per mm) spread over a box of 60 mm, so some pairs
// are beyond rMax; with a repeated position and one a hair's breadth (1e-20 mm) away,
// where Imath's length rescales to avoid underflow.
std::vector<SurfaceSample> randomSamples(std::size_t n, double unitsPerMm, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> position(0.0f, float(60.0 * unitsPerMm));
    std::uniform_real_distribution<float> area(0.1f, 2.0f);
    std::vector<SurfaceSample> s(n);
    for (SurfaceSample& x : s) {
        x.position = Imath::V3f(position(rng), position(rng), position(rng));
        x.area = area(rng) * float(unitsPerMm * unitsPerMm);
    }
    s[2].position = Imath::V3f(0.0f);  // near the origin, so that 1e-20 is representable
    s[5].position = s[2].position;
    s[9].position = Imath::V3f(1e-20f * float(unitsPerMm), 0.0f, 0.0f);
    return s;
}

TEST(TransferRow, MatchesDoublePrecisionEvaluation) {
    const double unitsPerMm = 0.1;
    const std::vector<SurfaceSample> samples = randomSamples(517, unitsPerMm, 3);
    for (int K : {5, 12}) {
        const ProfileBasis basis = makeLinearBasis(K);
        const BasisLookup lookup(basis);
        const TransferSamples mm = toTransferSamples(samples, unitsPerMm);
        const std::size_t n = samples.size();
        std::vector<float> rows(K * n);
        for (std::size_t o : {std::size_t(0), std::size_t(2), std::size_t(258), n - 1}) {
            transferRow(o, mm, lookup, rows);
            for (std::size_t i = 0; i < n; ++i) {
                const Imath::V3d d = (Imath::V3d(samples[i].position) - Imath::V3d(samples[o].position)) / unitsPerMm;
                const double r = d.length();
                if (std::abs(r - kRMax) < 1e-3) continue;  // float and double may fall either side of rMax
                const double area = double(samples[i].area) / (unitsPerMm * unitsPerMm);
                for (int k = 0; k < K; ++k) {
                    const double expected = linearBasis(k, r) * area;
                    ASSERT_NEAR(rows[k * n + i], expected, 1e-5 * (1.0 + std::abs(expected)))
                        << "K " << K << " o " << o << " i " << i << " k " << k << " r " << r;
                }
            }
        }
    }
}

TEST(TransferRow, MatchesThePerPairLoopBitForBit) {
    const double unitsPerMm = 1.0 / 3.0;
    const std::vector<SurfaceSample> samples = randomSamples(517, unitsPerMm, 4);
    const std::size_t n = samples.size();
    for (int K : {3, 12}) {
        const BasisLookup lookup(makeCurvedBasis(K));
        const TransferSamples mm = toTransferSamples(samples, unitsPerMm);
        std::vector<float> rows(K * n), b(K);
        const float toMm = float(1.0 / unitsPerMm);
        for (std::size_t o : {std::size_t(2), std::size_t(9), std::size_t(300), n - 1}) {
            transferRow(o, mm, lookup, rows);
            const Imath::V3f xo = samples[o].position * toMm;
            for (std::size_t i = 0; i < n; ++i) {
                lookup.evaluate((samples[i].position * toMm - xo).length(), b.data());
                const float a = samples[i].area * toMm * toMm;
                for (int k = 0; k < K; ++k) {
                    const float expected = b[k] * a;
                    ASSERT_EQ(std::memcmp(&rows[k * n + i], &expected, sizeof(float)), 0)
                        << "K " << K << " o " << o << " i " << i << " k " << k << ": " << rows[k * n + i] << " vs "
                        << expected;
                }
            }
        }
    }
}

TEST(TransferRow, PaddedStrideGivesTheSameRows) {
    const std::vector<SurfaceSample> samples = randomSamples(517, 1.0, 6);
    const std::size_t n = samples.size(), stride = transferRowStride(n);
    EXPECT_GE(stride, n + 16);
    EXPECT_EQ(stride % 16, 0u);  // whole cache lines
    const BasisLookup lookup(makeCurvedBasis(12));
    const TransferSamples mm = toTransferSamples(samples, 1.0);
    std::vector<float> dense(12 * n), padded(11 * stride + n, -3.0f);
    transferRow(7, mm, lookup, dense);
    transferRow(7, mm, lookup, padded, stride);
    for (std::size_t k = 0; k < 12; ++k) {
        for (std::size_t i = 0; i < n; ++i)
            ASSERT_EQ(std::memcmp(&padded[k * stride + i], &dense[k * n + i], sizeof(float)), 0) << k << ", " << i;
        for (std::size_t i = n; i < stride && k * stride + i < padded.size(); ++i) ASSERT_EQ(padded[k * stride + i], -3.0f);
    }
}

TEST(TransferRow, RejectsBadArguments) {
    const std::vector<SurfaceSample> samples = randomSamples(16, 1.0, 5);
    const TransferSamples mm = toTransferSamples(samples, 1.0);
    const BasisLookup lookup(makeLinearBasis(4));
    std::vector<float> rows(4 * 16);
    EXPECT_THROW(transferRow(16, mm, lookup, rows), Error);
    EXPECT_THROW(transferRow(0, mm, lookup, std::span<float>(rows).first(63)), Error);
    EXPECT_THROW(transferRow(0, mm, lookup, std::span<float>(rows).first(3 * 15 + 16), 15), Error);  // stride < N
    EXPECT_THROW(transferRow(0, mm, lookup, rows, 17), Error);  // 3 x 17 + 16 = 67 floats needed
    EXPECT_THROW(toTransferSamples(samples, 0.0), Error);
    EXPECT_THROW(toTransferSamples(samples, std::nan("")), Error);
}

}  // namespace
}  // namespace opal
