#include "schema/wavelet/sparse.h"

#include "tests/wavelet/wavelet_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace opal {
namespace {

SparseMatrix emptyMatrix(std::uint32_t cols) {
    SparseMatrix m;
    m.cols = cols;
    return m;
}

// A rows x cols matrix with about `perRow` random entries per row, and its dense copy.
struct TestMatrix {
    SparseMatrix sparse;
    std::vector<double> dense;
};

TestMatrix randomMatrix(std::uint32_t rows, std::uint32_t cols, std::uint32_t perRow,
                        std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<std::uint32_t> column(0, cols - 1);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    TestMatrix m{emptyMatrix(cols), std::vector<double>(std::size_t(rows) * cols, 0.0)};
    for (std::uint32_t r = 0; r < rows; ++r) {
        std::vector<float> row(cols, 0.0f);
        for (std::uint32_t k = 0; k < perRow; ++k) row[column(rng)] = value(rng);
        SparseVector entries = keepLargest(row, cols);
        appendRow(m.sparse, entries);
        for (std::uint32_t c = 0; c < cols; ++c) m.dense[std::size_t(r) * cols + c] = row[c];
    }
    return m;
}

std::vector<double> denseMultiply(const TestMatrix& m, const std::vector<float>& x,
                                  std::uint32_t channels) {
    const std::uint32_t rows = m.sparse.rows, cols = m.sparse.cols;
    std::vector<double> y(std::size_t(rows) * channels, 0.0);
    for (std::uint32_t r = 0; r < rows; ++r)
        for (std::uint32_t c = 0; c < cols; ++c)
            for (std::uint32_t ch = 0; ch < channels; ++ch)
                y[std::size_t(r) * channels + ch] +=
                    m.dense[std::size_t(r) * cols + c] * x[std::size_t(c) * channels + ch];
    return y;
}

TEST(SparseMatrix, AppendRowBuildsCompressedRows) {
    SparseMatrix m = emptyMatrix(5);
    appendRow(m, SparseVector{{1, 4}, {2.0f, 3.0f}});
    appendRow(m, SparseVector{});
    appendRow(m, SparseVector{{0}, {-1.0f}});
    EXPECT_EQ(m.rows, 3u);
    EXPECT_EQ(m.rowOffsets, (std::vector<std::uint64_t>{0, 2, 2, 3}));
    EXPECT_EQ(m.columns, (std::vector<std::uint32_t>{1, 4, 0}));
    EXPECT_EQ(m.values, (std::vector<float>{2.0f, 3.0f, -1.0f}));
    EXPECT_NO_THROW(validate(m, "test"));
    test::expectErrorContaining(
        [&] {
            appendRow(m, SparseVector{{5}, {1.0f}});
        },
        "appendRow: column 5 out of range (cols = 5)");
}

TEST(SparseMatrix, MultiplyMatchesDenseProduct) {
    // Small (serial) and large (parallel: over 65536 nonzeros) matrices, 1 to 3 channels.
    for (auto [rows, cols, perRow] : {std::tuple{7u, 9u, 3u}, std::tuple{1500u, 400u, 60u}})
        for (std::uint32_t channels : {1u, 2u, 3u}) {
            const TestMatrix m = randomMatrix(rows, cols, perRow, rows + channels);
            const std::vector<float> x =
                test::randomValues<float>(std::size_t(cols) * channels, 51);
            std::vector<float> y(std::size_t(rows) * channels, 99.0f);  // overwritten
            multiply(m.sparse, x, y, channels);
            const std::vector<double> expected = denseMultiply(m, x, channels);
            for (std::size_t i = 0; i < y.size(); ++i)
                ASSERT_NEAR(y[i], expected[i], 1e-4)
                    << rows << " rows, channels " << channels << ", " << i;
        }
}

TEST(SparseMatrix, MultiplyRejectsSizeMismatch) {
    const TestMatrix m = randomMatrix(4, 6, 2, 1);
    std::vector<float> x(18), y(12);
    EXPECT_NO_THROW(multiply(m.sparse, x, y));
    test::expectErrorContaining(
        [&] { multiply(m.sparse, std::span(x).first(17), y); },
        "4 x 6 matrix with 3 channels needs x of 18 and y of 12 values, got 17 and 12");
    EXPECT_THROW(multiply(m.sparse, x, y, 0), Error);
}

// Each corruption of a valid matrix must be caught, with the context in the message.
TEST(SparseMatrix, ValidateRejectsInconsistentData) {
    SparseMatrix valid = emptyMatrix(4);
    appendRow(valid, SparseVector{{0, 3}, {1.0f, 2.0f}});
    appendRow(valid, SparseVector{{1, 2}, {3.0f, 4.0f}});
    ASSERT_NO_THROW(validate(valid, "ctx"));

    auto expectInvalid = [&](auto corrupt, std::string_view message) {
        SparseMatrix m = valid;
        corrupt(m);
        test::expectErrorContaining(
            [&] { validate(m, "candle.opal: chunk TRN0"); },
            std::string("candle.opal: chunk TRN0: sparse matrix ") + std::string(message));
    };
    expectInvalid([](SparseMatrix& m) { m.rows = 3; }, "has 3 row offsets, expected rows + 1 = 4");
    expectInvalid([](SparseMatrix& m) { m.rowOffsets[0] = 1; }, "row offsets start at 1");
    expectInvalid([](SparseMatrix& m) { m.rowOffsets[1] = 5; }, "row 1 ends before it starts");
    expectInvalid([](SparseMatrix& m) { m.rowOffsets[2] = 3; },
                  "row offsets end at 3 but there are 4 values");
    expectInvalid([](SparseMatrix& m) { m.columns.pop_back(); },
                  "has 3 column indices for 4 values");
    expectInvalid([](SparseMatrix& m) { m.columns[1] = 4; },
                  "row 0 entry 1: column 4 out of range");
    expectInvalid([](SparseMatrix& m) { m.columns[3] = 1; },
                  "row 1 entry 3: columns not strictly ascending");
    expectInvalid([](SparseMatrix& m) { m.values[2] = NAN; }, "row 1 entry 2: value is not finite");
}

}  // namespace
}  // namespace opal
