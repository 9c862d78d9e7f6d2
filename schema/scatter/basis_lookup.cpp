#include "schema/error.h"
#include "schema/scatter/profile_basis.h"

#include <algorithm>
#include <cmath>
#include <string>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace opal {

namespace {

// Where radius r falls in the table: u * resolution = sqrt(r) * scale, in interval `row`
// at fraction t. False beyond rMax, for r < 0 and NaN.
struct TablePosition {
    int row = 0;
    float t = 0.0f;
};

bool tablePosition(float r, float scale, int resolution, TablePosition& at) {
    const float x = std::sqrt(r) * scale;  // NaN for r < 0
    if (!(x <= static_cast<float>(resolution))) return false;
    at.row = std::min(static_cast<int>(x), resolution - 1);
    at.t = x - static_cast<float>(at.row);
    return true;
}

}  // namespace

// The samples are b_k(rMax (i / resolution)^2), i = 0..resolution: uniform in
// u = sqrt(r / rMax), so they are dense near r = 0 where the profiles peak. Interval i
// stores its start value and its step (a float difference of the two float samples, as
// interpolation computed it before); both are padded with zeros to a multiple of 4 values,
// so that evaluateWeighted can interpolate four k at a time.
BasisLookup::BasisLookup(const ProfileBasis& basis, int resolution)
    : K_(basis.K()), width_((basis.K() + 3) / 4 * 4), resolution_(resolution),
      rMax_(static_cast<float>(basis.rMax())) {
    if (resolution < 1) throw Error("BasisLookup: resolution = " + std::to_string(resolution) + " must be >= 1");
    if (K_ < 1 || !(basis.rMax() > 0.0)) throw Error("BasisLookup: the profile basis is empty");
    scale_ = static_cast<float>(resolution / std::sqrt(basis.rMax()));
    auto sample = [&](int k, int i) {
        const double u = static_cast<double>(i) / resolution;
        return static_cast<float>(basis.evaluate(k, std::min(basis.rMax() * u * u, basis.rMax())));
    };
    table_.assign(static_cast<std::size_t>(resolution + 1) * 2 * width_, 0.0f);
    for (int i = 0; i < resolution; ++i) {
        float* start = table_.data() + static_cast<std::size_t>(i) * 2 * width_;
        for (int k = 0; k < K_; ++k) {
            start[k] = sample(k, i);
            start[width_ + k] = sample(k, i + 1) - start[k];
        }
    }
}

void BasisLookup::evaluate(float r, float* out) const {
    TablePosition at;
    if (!tablePosition(r, scale_, resolution_, at)) {
        std::fill_n(out, K_, 0.0f);
        return;
    }
    const float* start = table_.data() + static_cast<std::size_t>(at.row) * 2 * width_;
    const float* step = start + width_;
    for (int k = 0; k < K_; ++k) out[k] = start[k] + at.t * step[k];
}

#if defined(__SSE2__)
namespace {

// The SSE form of tablePosition for four radii. min(int(x), res - 1) equals
// int(min(x, res - 1)) for the valid x in [0, res]. Radii outside the table get the zero
// row `resolution` and t = 0, so they interpolate to +0 exactly as evaluate() fills in.
struct FourPositions {
    alignas(16) int row[4];
    __m128 t;
};

FourPositions tablePositions(const float* r, float scale, int resolution) {
    const __m128 x = _mm_mul_ps(_mm_sqrt_ps(_mm_loadu_ps(r)), _mm_set1_ps(scale));
    const __m128 valid = _mm_cmple_ps(x, _mm_set1_ps(static_cast<float>(resolution)));  // false for NaN
    const __m128i inside = _mm_cvttps_epi32(_mm_min_ps(x, _mm_set1_ps(static_cast<float>(resolution - 1))));
    const __m128i row = _mm_or_si128(_mm_and_si128(_mm_castps_si128(valid), inside),
                                     _mm_andnot_si128(_mm_castps_si128(valid), _mm_set1_epi32(resolution)));
    FourPositions p;
    _mm_store_si128(reinterpret_cast<__m128i*>(p.row), row);
    p.t = _mm_and_ps(valid, _mm_sub_ps(x, _mm_cvtepi32_ps(inside)));
    return p;
}

template <int Lane>
__m128 broadcast(__m128 v) {
    return _mm_shuffle_ps(v, v, _MM_SHUFFLE(Lane, Lane, Lane, Lane));
}

// The table as the SSE kernel needs it.
struct TableView {
    const float* table;
    int width, K, resolution;
    float scale;
};

// Radii 4 at a time (the first count - count % 4), `blocks` groups of four k each: each
// lane interpolates four k of its interval (a vector over k); a 4 x 4 transpose turns those
// into vectors over j, which are weighted and stored to four output rows. kBlocks > 0 fixes
// the block count at compile time (the loop unrolls, everything stays in registers); 0
// reads it from `blocks`. Returns how many radii were done.
template <int kBlocks>
std::size_t weightedFours(const TableView& v, int blocks, const float* r, const float* weight, std::size_t count,
                          float* rows, std::size_t stride) {
    const int K = v.K, width = v.width, blockCount = kBlocks > 0 ? kBlocks : blocks;
    std::size_t j = 0;
    for (; j + 4 <= count; j += 4) {
        const FourPositions p = tablePositions(r + j, v.scale, v.resolution);
        const __m128 w = _mm_loadu_ps(weight + j);
        const __m128 t[4] = {broadcast<0>(p.t), broadcast<1>(p.t), broadcast<2>(p.t), broadcast<3>(p.t)};
        const float* start[4];
        for (int l = 0; l < 4; ++l) start[l] = v.table + static_cast<std::size_t>(p.row[l]) * 2 * width;
        for (int block = 0; block < blockCount; ++block) {
            const int k = 4 * block;
            __m128 b[4];
            for (int l = 0; l < 4; ++l)
                b[l] = _mm_add_ps(_mm_loadu_ps(start[l] + k), _mm_mul_ps(t[l], _mm_loadu_ps(start[l] + width + k)));
            _MM_TRANSPOSE4_PS(b[0], b[1], b[2], b[3]);
            const int outputs = std::min(4, K - k);  // the last block may be padding
            for (int q = 0; q < outputs; ++q) _mm_storeu_ps(rows + (k + q) * stride + j, _mm_mul_ps(b[q], w));
        }
    }
    return j;
}

}  // namespace
#endif

void BasisLookup::evaluateWeighted(std::span<const float> r, std::span<const float> weight, float* rows,
                                   std::size_t stride) const {
    const std::size_t count = r.size();
    const std::size_t rowFloats = 2 * static_cast<std::size_t>(width_);
    std::size_t j = 0;
#if defined(__SSE2__)
    const TableView view{table_.data(), width_, K_, resolution_, scale_};
    const int blocks = width_ / 4;
    switch (blocks) {  // the usual K (up to 16) get an unrolled kernel
    case 1: j = weightedFours<1>(view, blocks, r.data(), weight.data(), count, rows, stride); break;
    case 2: j = weightedFours<2>(view, blocks, r.data(), weight.data(), count, rows, stride); break;
    case 3: j = weightedFours<3>(view, blocks, r.data(), weight.data(), count, rows, stride); break;
    case 4: j = weightedFours<4>(view, blocks, r.data(), weight.data(), count, rows, stride); break;
    default: j = weightedFours<0>(view, blocks, r.data(), weight.data(), count, rows, stride); break;
    }
#endif
    for (; j < count; ++j) {
        TablePosition at{resolution_, 0.0f};  // the zero row unless r is inside the table
        tablePosition(r[j], scale_, resolution_, at);
        const float* start = table_.data() + static_cast<std::size_t>(at.row) * rowFloats;
        for (int k = 0; k < K_; ++k) rows[k * stride + j] = (start[k] + at.t * start[width_ + k]) * weight[j];
    }
}

}  // namespace opal
