// TransferProduct: the compact working copy of the transfer against the asset's floats.
#include "delegate/relight/transfer_product.h"

#include "schema/error.h"

#include <Imath/half.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace opal {
namespace {

// A random sparse samples x samples matrix with `perRow` distinct ascending columns per row
// and values spread over `decades` powers of ten.
SparseMatrix randomMatrix(std::uint32_t samples, std::uint32_t perRow, double decades, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    SparseMatrix m;
    m.rows = m.cols = samples;
    m.rowOffsets.push_back(0);
    for (std::uint32_t r = 0; r < samples; ++r) {
        const std::uint32_t stride = samples / perRow;
        for (std::uint32_t j = 0; j < perRow; ++j) {
            m.columns.push_back(j * stride + std::uint32_t(unit(rng) * (stride - 1)));
            const double sign = unit(rng) < 0.5 ? -1.0 : 1.0;
            m.values.push_back(float(sign * std::pow(10.0, -decades * unit(rng))));
        }
        m.rowOffsets.push_back(m.values.size());
    }
    return m;
}

struct Product {
    std::vector<float> y;      // (r * K + k) * C + c
    std::vector<double> bound; // sum |a| |x| per output: the scale of the allowed rounding
};

// The exact product in double from the asset's floats.
Product exactProduct(const CompressedTransfer& t, const std::vector<float>& x, std::size_t lanes, std::size_t C) {
    const std::size_t K = t.perBasis.size(), N = t.perBasis[0].rows;
    Product p{std::vector<float>(N * K * C), std::vector<double>(N * K * C)};
    for (std::size_t k = 0; k < K; ++k)
        for (std::size_t r = 0; r < N; ++r)
            for (std::size_t c = 0; c < C; ++c) {
                double sum = 0.0, bound = 0.0;
                const SparseMatrix& m = t.perBasis[k];
                for (std::uint64_t e = m.rowOffsets[r]; e < m.rowOffsets[r + 1]; ++e) {
                    const double a = m.values[e], v = x[m.columns[e] * lanes + c];
                    sum += a * v;
                    bound += std::abs(a * v);
                }
                p.y[(r * K + k) * C + c] = float(sum);
                p.bound[(r * K + k) * C + c] = bound;
            }
    return p;
}

std::vector<float> paddedInput(std::size_t samples, std::size_t lanes, std::size_t C, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    std::vector<float> x(samples * lanes, 0.0f);
    for (std::size_t j = 0; j < samples; ++j)
        for (std::size_t c = 0; c < C; ++c) x[j * lanes + c] = value(rng);
    return x;
}

// Every output within 2^-11 sum |a||x| (binary16's relative rounding) plus float sums.
void expectProductMatches(const CompressedTransfer& t, std::size_t lanes, std::size_t C, TransferProduct::Kernel kernel,
                          const std::vector<std::uint32_t>& slots) {
    const std::size_t N = t.perBasis[0].rows, K = t.perBasis.size();
    const TransferProduct product(t, N, kernel, slots);
    ASSERT_EQ(product.kernel(), kernel);
    const std::vector<float> x = paddedInput(N, lanes, C, 7);
    std::vector<float> arranged(x.size(), 0.0f);
    product.arrangeInput(x, lanes, arranged);
    // Rows split unevenly, as threads take them: every output written once, whatever order
    // the rows are stored in.
    std::vector<float> y(N * K * C, std::numeric_limits<float>::quiet_NaN());
    const std::uint32_t n = std::uint32_t(N), a = n / 3, b = std::min(n, a + 7);
    for (const auto& [begin, end] : {std::pair{0u, a}, std::pair{a, b}, std::pair{b, n}})
        product.multiplyRows(arranged.data(), lanes, y.data(), C, begin, end);
    const Product exact = exactProduct(t, x, lanes, C);
    for (std::size_t i = 0; i < y.size(); ++i)
        ASSERT_NEAR(y[i], exact.y[i], std::ldexp(1.0, -11) * exact.bound[i] + 1e-6 * exact.bound[i]) << "output " << i;
}

// Each kernel this CPU has (the portable one always).
std::vector<TransferProduct::Kernel> kernels() {
    std::vector<TransferProduct::Kernel> all{TransferProduct::Kernel::Portable};
    for (TransferProduct::Kernel kernel : {TransferProduct::Kernel::Avx2, TransferProduct::Kernel::Avx512})
        if (TransferProduct::kernelAvailable(kernel)) all.push_back(kernel);
    return all;
}

// Every kernel, with wE read in its own order and in a shuffled one.
void expectProductMatches(const CompressedTransfer& t, std::size_t lanes, std::size_t C) {
    std::vector<std::uint32_t> shuffled(t.perBasis[0].rows);
    std::iota(shuffled.begin(), shuffled.end(), 0u);
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(5));
    for (TransferProduct::Kernel kernel : kernels())
        for (const std::vector<std::uint32_t>& slots : {std::vector<std::uint32_t>{}, shuffled}) {
            SCOPED_TRACE(slots.empty() ? "own order" : "shuffled slots");
            expectProductMatches(t, lanes, C, kernel, slots);
        }
}

CompressedTransfer randomTransfer(std::uint32_t samples, std::size_t K) {
    CompressedTransfer t;
    for (std::size_t k = 0; k < K; ++k) t.perBasis.push_back(randomMatrix(samples, 16, 3.0, std::uint32_t(11 + k)));
    return t;
}

TEST(NormalHalfToFloat, EqualsImathForEveryNormalHalf) {
    for (std::uint32_t bits = 0; bits < 0x10000u; ++bits) {
        const std::uint32_t exponent = (bits >> 10) & 0x1fu;
        if (exponent == 0 || exponent == 31) continue;  // zero/subnormal and inf/NaN are never stored
        Imath::half h;
        h.setBits(std::uint16_t(bits));
        ASSERT_EQ(normalHalfToFloat(std::uint16_t(bits)), float(h)) << "bits " << bits;
    }
}

TEST(TransferProduct, MatchesTheExactProductForEveryLaneWidth) {
    const CompressedTransfer t = randomTransfer(256, 3);
    expectProductMatches(t, 4, 3);
    expectProductMatches(t, 8, 6);
    expectProductMatches(t, 12, 9);
}

// Row r holds r mod 22 entries: empty rows, rows shorter than a vector's 8 values, and
// whole vectors with every tail length after them.
TEST(TransferProduct, MatchesTheExactProductForRowsOfEveryLength) {
    CompressedTransfer t;
    for (std::uint32_t k = 0; k < 2; ++k) {
        const SparseMatrix full = randomMatrix(264, 22, 3.0, 31 + k);
        SparseMatrix m;
        m.rows = m.cols = full.rows;
        m.rowOffsets.push_back(0);
        for (std::uint32_t r = 0; r < full.rows; ++r) {
            const std::uint64_t begin = full.rowOffsets[r], count = r % 22;
            m.columns.insert(m.columns.end(), full.columns.begin() + begin, full.columns.begin() + begin + count);
            m.values.insert(m.values.end(), full.values.begin() + begin, full.values.begin() + begin + count);
            m.rowOffsets.push_back(m.values.size());
        }
        t.perBasis.push_back(std::move(m));
    }
    expectProductMatches(t, 4, 3);
    expectProductMatches(t, 8, 6);
    expectProductMatches(t, 12, 9);
}

TEST(TransferProduct, WideColumnsBeyond65536Samples) {
    // 70,000 samples need 32-bit columns; 11 entries per row (a whole vector of 8 and a tail)
    // keep the test fast.
    CompressedTransfer t;
    t.perBasis.push_back(randomMatrix(70000, 11, 2.0, 3));
    const TransferProduct product(t, 70000);
    const SparseMatrix& m = t.perBasis[0];
    for (std::uint32_t r = 0; r < 70000; r += 7)
        for (std::uint64_t i = m.rowOffsets[r]; i < m.rowOffsets[r + 1]; ++i)
            ASSERT_NEAR(product.value(0, r, m.columns[i]), m.values[i], std::ldexp(std::abs(m.values[i]), -11));
    EXPECT_GT(*std::max_element(t.perBasis[0].columns.begin(), t.perBasis[0].columns.end()), 65536u);
    expectProductMatches(t, 4, 3);
    expectProductMatches(t, 8, 6);
}

TEST(TransferProduct, ValuesKeepElevenSignificantBitsAndDropOnlyTheNegligible) {
    CompressedTransfer t;
    SparseMatrix m = randomMatrix(64, 8, 12.0, 5);  // 12 decades: some fall below 2^-28 of the largest
    t.perBasis.push_back(m);
    const TransferProduct product(t, 64);
    float largest = 0.0f;
    for (float v : m.values) largest = std::max(largest, std::abs(v));
    std::uint64_t kept = 0, dropped = 0;
    for (std::uint32_t r = 0; r < 64; ++r)
        for (std::uint64_t i = m.rowOffsets[r]; i < m.rowOffsets[r + 1]; ++i) {
            const float stored = product.value(0, r, m.columns[i]);
            if (stored != 0.0f) {
                EXPECT_NEAR(stored, m.values[i], std::ldexp(std::abs(m.values[i]), -11));
                ++kept;
            } else {
                EXPECT_LT(std::abs(m.values[i]), std::ldexp(largest, -28)) << "row " << r << " entry " << i;
                ++dropped;
            }
        }
    EXPECT_GT(dropped, 0u);
    EXPECT_EQ(kept, product.nonZeros());
}

// Two matrices with no column in common and two with every column in common: a pair's
// shared column list holds each value once, in its own matrix, and zeros where only the
// other matrix has an entry.
TEST(TransferProduct, PairsShareColumnsWithoutMixingTheirValues) {
    CompressedTransfer t;
    SparseMatrix even = randomMatrix(96, 6, 2.0, 41), odd = even;
    for (std::uint32_t& c : odd.columns) ++c;  // one column per 16 wide block, below its last: disjoint
    for (float& v : odd.values) v = -2.0f * v;
    t.perBasis = {even, odd, even, even};
    const TransferProduct product(t, 96);
    for (std::uint32_t r = 0; r < 96; ++r)
        for (std::size_t k = 0; k < 4; ++k) {
            const SparseMatrix& m = t.perBasis[k];
            for (std::uint32_t c = 0; c < 96; ++c) {
                const auto begin = m.columns.begin() + std::ptrdiff_t(m.rowOffsets[r]);
                const auto end = m.columns.begin() + std::ptrdiff_t(m.rowOffsets[r + 1]);
                const auto at = std::find(begin, end, c);
                const float expected = at == end ? 0.0f : m.values[std::size_t(at - m.columns.begin())];
                ASSERT_NEAR(product.value(k, r, c), expected, std::ldexp(std::abs(expected), -11))
                    << "matrix " << k << " row " << r << " column " << c;
            }
        }
    EXPECT_EQ(product.nonZeros(), 4u * 96u * 6u);
    expectProductMatches(t, 8, 6);
}

TEST(TransferProduct, InputSlotsThatAreNotAPermutationAreRefused) {
    const CompressedTransfer t = randomTransfer(32, 2);
    std::vector<std::uint32_t> slots(32);
    std::iota(slots.begin(), slots.end(), 0u);
    slots[3] = 4;
    EXPECT_THROW(TransferProduct(t, 32, TransferProduct::Kernel::Best, slots), Error);
    slots.pop_back();
    EXPECT_THROW(TransferProduct(t, 32, TransferProduct::Kernel::Best, slots), Error);
}

TEST(TransferProduct, BestIsTheFastestKernelTheCpuHas) {
    const CompressedTransfer t = randomTransfer(32, 1);
    EXPECT_EQ(TransferProduct(t, 32).kernel(), kernels().back());
    for (TransferProduct::Kernel kernel : {TransferProduct::Kernel::Avx2, TransferProduct::Kernel::Avx512})
        if (!TransferProduct::kernelAvailable(kernel)) {
            EXPECT_THROW(TransferProduct(t, 32, kernel), Error);
        }
}

TEST(TransferProduct, RejectsInconsistentMatrices) {
    CompressedTransfer t = randomTransfer(32, 1);
    EXPECT_THROW(TransferProduct(t, 64), Error);  // shape
    t.perBasis[0].columns[5] = 32;
    EXPECT_THROW(TransferProduct(t, 32), Error);  // column out of range
    t = randomTransfer(32, 1);
    t.perBasis[0].values[3] = std::nanf("");
    EXPECT_THROW(TransferProduct(t, 32), Error);
    t = randomTransfer(32, 1);
    t.perBasis[0].rowOffsets[4] = t.perBasis[0].rowOffsets[2];  // offsets that fall
    EXPECT_THROW(TransferProduct(t, 32), Error);
    t = randomTransfer(32, 1);
    t.perBasis[0].columns[1] = t.perBasis[0].columns[0];  // a column twice in a row
    EXPECT_THROW(TransferProduct(t, 32), Error);
    t = randomTransfer(32, 1);
    const TransferProduct product(t, 32);
    std::vector<float> x(32 * 4), y(32 * 3);
    EXPECT_THROW(product.multiplyRows(x.data(), 6, y.data(), 3, 0, 32), Error);  // lanes
    EXPECT_THROW(product.multiplyRows(x.data(), 4, y.data(), 3, 5, 3), Error);   // rows backwards
    EXPECT_THROW(product.multiplyRows(x.data(), 4, y.data(), 3, 0, 33), Error);  // past the last row
}

}  // namespace
}  // namespace opal
