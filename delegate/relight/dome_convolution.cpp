#include "delegate/relight/dome_convolution.h"

#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace opal {

namespace {

constexpr std::uint32_t kNodes = DomeConvolution::kGridSize;

float signOf(float x) { return x >= 0.0f ? 1.0f : -1.0f; }

// Octahedral map: the unit sphere onto [-1, 1]^2, the lower hemisphere folded over the corners.
Imath::V3f octahedralDirection(float u, float v) {
    float x = u, y = v;
    const float z = 1.0f - std::abs(u) - std::abs(v);
    if (z < 0.0f) x = (1.0f - std::abs(v)) * signOf(u), y = (1.0f - std::abs(u)) * signOf(v);
    return Imath::V3f(x, y, z).normalized();
}

Imath::V2f octahedralPoint(const Imath::V3f& n) {
    const float l1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    if (!(l1 > 0.0f)) return {0.0f, 0.0f};  // not a direction: the map's centre, +z
    float x = n.x / l1, y = n.y / l1;
    if (n.z < 0.0f) {
        const float fx = x;
        x = (1.0f - std::abs(y)) * signOf(fx), y = (1.0f - std::abs(fx)) * signOf(y);
    }
    return {x, y};
}

// k_m(mu) = max(0, mu) P_m(mu) for one basis, moments 0 .. M-1.
template <FresnelBasis B, std::uint32_t M>
inline void kernel(float mu, float* k) {
    const float w = std::max(mu, 0.0f);
    k[0] = w;
    if constexpr (B == FresnelBasis::Schlick) {
        const float s = 1.0f - mu, s2 = s * s;
        if constexpr (M > 1) k[1] = w * (s2 * s2 * s);
        if constexpr (M > 2) k[2] = w * s2;
    } else {
        if constexpr (M > 1) k[1] = w * (2.0f * mu - 1.0f);
        if constexpr (M > 2) k[2] = w * ((6.0f * mu - 6.0f) * mu + 1.0f);
    }
}

// sum_t k_m(n.w_t) L_t over the texels of the given [begin, end) ranges, for one basis and
// moment count. kLanes partial sums per value, so that the compiler vectorizes across them
// without reordering any one sum (the result does not depend on the instruction set).
constexpr std::uint32_t kLanes = 8;

template <FresnelBasis B, std::uint32_t M>
void accumulate(const Imath::V3f& n, std::span<const std::pair<std::uint32_t, std::uint32_t>> ranges,
                const float* dx, const float* dy, const float* dz, const float* red, const float* green,
                const float* blue, float* out) {
    float r[M][kLanes] = {}, g[M][kLanes] = {}, b[M][kLanes] = {};
    const auto add = [&](std::uint32_t t, std::uint32_t l) {
        float k[M];
        kernel<B, M>(n.x * dx[t] + n.y * dy[t] + n.z * dz[t], k);
        for (std::uint32_t m = 0; m < M; ++m) r[m][l] += k[m] * red[t], g[m][l] += k[m] * green[t], b[m][l] += k[m] * blue[t];
    };
    for (const auto& [begin, end] : ranges) {
        std::uint32_t t = begin;
        for (; t + kLanes <= end; t += kLanes)
            for (std::uint32_t l = 0; l < kLanes; ++l) add(t + l, l);
        for (; t < end; ++t) add(t, 0);
    }
    for (std::uint32_t m = 0; m < M; ++m) {
        float sums[3] = {};
        for (std::uint32_t l = 0; l < kLanes; ++l) sums[0] += r[m][l], sums[1] += g[m][l], sums[2] += b[m][l];
        for (int c = 0; c < 3; ++c) out[3 * m + c] = sums[c];
    }
}

}  // namespace

DomeConvolution::DomeConvolution(const CubeMapLayout& cube, std::span<const float> radiance, std::uint32_t terms,
                                 FresnelBasis basis)
    : terms_(terms), basis_(basis) {
    if (terms < 1 || terms > std::uint32_t(kMaxFresnelTerms))
        throw Error("dome convolution: 1 to " + std::to_string(kMaxFresnelTerms) + " Fresnel terms, got " +
                    std::to_string(terms));
    if (radiance.size() != std::size_t(cube.texels()) * 3)
        throw Error("dome convolution: " + std::to_string(radiance.size()) + " radiance values for " +
                    std::to_string(cube.texels()) + " RGB texels");
    for (std::uint32_t t = 0; t < cube.texels(); ++t) {
        const Imath::V3f d = cube.direction(t);
        const float solidAngle = float(cube.solidAngle(t));
        dx_.push_back(d.x), dy_.push_back(d.y), dz_.push_back(d.z);
        red_.push_back(radiance[3 * t] * solidAngle);
        green_.push_back(radiance[3 * t + 1] * solidAngle);
        blue_.push_back(radiance[3 * t + 2] * solidAngle);
    }
    // A row of a face lies between two lines of constant v, which the sphere sees as great
    // circles: it is a convex spherical quadrilateral, wholly below a normal's horizon when
    // its four corners are.
    faceSize_ = cube.faceSize();
    for (std::uint32_t face = 0; face < 6; ++face)
        for (std::uint32_t v = 0; v < faceSize_; ++v)
            for (std::uint32_t corner = 0; corner < 4; ++corner)
                rowCorners_.push_back(CubeMapLayout::faceDirection(
                    face, corner % 2 ? 1.0f : -1.0f, 2.0f * float(v + corner / 2) / float(faceSize_) - 1.0f));
    nodes_.resize(std::size_t(kNodes) * kNodes * terms * 3);
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, kNodes * kNodes, 8), [&](const auto& range) {
        for (std::uint32_t node = range.begin(); node != range.end(); ++node) {
            const float u = -1.0f + 2.0f * float(node % kNodes) / float(kNodes - 1);
            const float v = -1.0f + 2.0f * float(node / kNodes) / float(kNodes - 1);
            sum(octahedralDirection(u, v), nodes_.data() + std::size_t(node) * terms_ * 3);
        }
    });
}

void DomeConvolution::sum(const Imath::V3f& n, float* out) const {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> rows;  // texel ranges above the horizon
    for (std::uint32_t row = 0; row < 6 * faceSize_; ++row) {
        const Imath::V3f* c = rowCorners_.data() + 4 * std::size_t(row);
        if (n.dot(c[0]) <= 0.0f && n.dot(c[1]) <= 0.0f && n.dot(c[2]) <= 0.0f && n.dot(c[3]) <= 0.0f) continue;
        const std::uint32_t begin = row * faceSize_;
        if (!rows.empty() && rows.back().second == begin)
            rows.back().second += faceSize_;
        else
            rows.emplace_back(begin, begin + faceSize_);
    }
    const auto run = [&](auto basis, auto moments) {
        accumulate<decltype(basis)::value, decltype(moments)::value>(n, rows, dx_.data(), dy_.data(), dz_.data(),
                                                                      red_.data(), green_.data(), blue_.data(), out);
    };
    using Schlick = std::integral_constant<FresnelBasis, FresnelBasis::Schlick>;
    using Legendre = std::integral_constant<FresnelBasis, FresnelBasis::Legendre>;
    const bool schlick = basis_ == FresnelBasis::Schlick;
    switch (terms_) {
        case 1: schlick ? run(Schlick{}, std::integral_constant<std::uint32_t, 1>{})
                        : run(Legendre{}, std::integral_constant<std::uint32_t, 1>{}); break;
        case 2: schlick ? run(Schlick{}, std::integral_constant<std::uint32_t, 2>{})
                        : run(Legendre{}, std::integral_constant<std::uint32_t, 2>{}); break;
        default: schlick ? run(Schlick{}, std::integral_constant<std::uint32_t, 3>{})
                         : run(Legendre{}, std::integral_constant<std::uint32_t, 3>{}); break;
    }
}

std::vector<float> DomeConvolution::exact(const Imath::V3f& normal) const {
    std::vector<float> out(std::size_t(terms_) * 3);
    sum(normal, out.data());
    return out;
}

void DomeConvolution::add(const Imath::V3f& normal, const Imath::V3f& scale, float* moments) const {
    const Imath::V2f p = octahedralPoint(normal);
    const float x = std::clamp((p.x + 1.0f) * 0.5f * float(kNodes - 1), 0.0f, float(kNodes - 1));
    const float y = std::clamp((p.y + 1.0f) * 0.5f * float(kNodes - 1), 0.0f, float(kNodes - 1));
    const std::uint32_t ix = std::min(std::uint32_t(x), kNodes - 2), iy = std::min(std::uint32_t(y), kNodes - 2);
    const float fx = x - float(ix), fy = y - float(iy);
    const std::size_t stride = std::size_t(terms_) * 3;
    const float* a = nodes_.data() + (std::size_t(iy) * kNodes + ix) * stride;
    const float* b = a + stride;
    const float* c = a + kNodes * stride;
    const float* d = c + stride;
    for (std::size_t k = 0; k < stride; k += 3)
        for (int ch = 0; ch < 3; ++ch) {
            const std::size_t j = k + std::size_t(ch);
            moments[j] += scale[ch] * ((1.0f - fy) * ((1.0f - fx) * a[j] + fx * b[j]) + fy * ((1.0f - fx) * c[j] + fx * d[j]));
        }
}

}  // namespace opal
