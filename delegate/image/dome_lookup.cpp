#include "delegate/image/dome_lookup.h"

#include "delegate/image/lat_long_lookup.h"
#include "schema/error.h"

#include <algorithm>
#include <numbers>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define OPAL_DOME_LOOKUP_AVX2 1
#include <immintrin.h>
#else
#define OPAL_DOME_LOOKUP_AVX2 0
#endif

namespace opal {

namespace {

#if OPAL_DOME_LOOKUP_AVX2
// lat_long_lookup.cpp's float fastAtan2, eight lanes: the same polynomial and quadrant steps.
__attribute__((target("avx2,fma"))) __m256 atan2x8(__m256 y, __m256 x) {
    const __m256 signMask = _mm256_set1_ps(-0.0f), zero = _mm256_setzero_ps();
    const __m256 ax = _mm256_andnot_ps(signMask, x), ay = _mm256_andnot_ps(signMask, y);
    const __m256 mx = _mm256_max_ps(ax, ay), mn = _mm256_min_ps(ax, ay);
    const __m256 t = _mm256_blendv_ps(zero, _mm256_div_ps(mn, mx), _mm256_cmp_ps(mx, zero, _CMP_GT_OQ));
    const __m256 z = _mm256_mul_ps(t, t);
    __m256 p = _mm256_fmadd_ps(z, _mm256_set1_ps(-0.01172120f), _mm256_set1_ps(0.05265332f));
    p = _mm256_fmadd_ps(z, p, _mm256_set1_ps(-0.11643287f));
    p = _mm256_fmadd_ps(z, p, _mm256_set1_ps(0.19354346f));
    p = _mm256_fmadd_ps(z, p, _mm256_set1_ps(-0.33262347f));
    p = _mm256_fmadd_ps(z, p, _mm256_set1_ps(0.99997726f));
    __m256 a = _mm256_mul_ps(t, p);
    a = _mm256_blendv_ps(a, _mm256_sub_ps(_mm256_set1_ps(float(std::numbers::pi / 2.0)), a),
                         _mm256_cmp_ps(ay, ax, _CMP_GT_OQ));
    a = _mm256_blendv_ps(a, _mm256_sub_ps(_mm256_set1_ps(float(std::numbers::pi)), a), _mm256_cmp_ps(x, zero, _CMP_LT_OQ));
    return _mm256_blendv_ps(a, _mm256_xor_ps(a, signMask), _mm256_cmp_ps(y, zero, _CMP_LT_OQ));
}

// LatLongMap::bilinear on eight (u, v): floor(t) as int(t + 1) - 1, wrap in longitude,
// clamp at the poles, a + (b - a) f; the texels gathered.
__attribute__((target("avx2,fma"))) void bilinearx8(const LatLongMap::LevelPixels& level, __m256 u, __m256 v,
                                                    __m256 rgb[3]) {
    const __m256 one = _mm256_set1_ps(1.0f), zero = _mm256_setzero_ps(), half = _mm256_set1_ps(0.5f);
    u = _mm256_min_ps(_mm256_max_ps(u, zero), one);
    v = _mm256_min_ps(_mm256_max_ps(v, zero), one);
    const __m256 x = _mm256_fmadd_ps(u, _mm256_set1_ps(float(level.width)), half);
    const __m256 y = _mm256_fmadd_ps(v, _mm256_set1_ps(float(level.height)), half);
    const __m256i xi = _mm256_cvttps_epi32(x), yi = _mm256_cvttps_epi32(y);
    const __m256 fx = _mm256_sub_ps(x, _mm256_cvtepi32_ps(xi)), fy = _mm256_sub_ps(y, _mm256_cvtepi32_ps(yi));
    const __m256i w = _mm256_set1_epi32(level.width), oneI = _mm256_set1_epi32(1), zeroI = _mm256_setzero_si256();
    __m256i xa = _mm256_sub_epi32(xi, oneI);
    xa = _mm256_add_epi32(xa, _mm256_and_si256(_mm256_cmpgt_epi32(zeroI, xa), w));                         // < 0: + width
    __m256i xb = _mm256_sub_epi32(xi, _mm256_andnot_si256(_mm256_cmpgt_epi32(w, xi), w));                  // >= width: - width
    const __m256i lastRow = _mm256_set1_epi32(level.height - 1);
    const __m256i ya = _mm256_min_epi32(_mm256_max_epi32(_mm256_sub_epi32(yi, oneI), zeroI), lastRow);
    const __m256i yb = _mm256_min_epi32(yi, lastRow);
    const __m256i three = _mm256_set1_epi32(3);
    const __m256i rowA = _mm256_mullo_epi32(_mm256_mullo_epi32(ya, w), three);
    const __m256i rowB = _mm256_mullo_epi32(_mm256_mullo_epi32(yb, w), three);
    const __m256i colA = _mm256_mullo_epi32(xa, three), colB = _mm256_mullo_epi32(xb, three);
    const __m256i aa = _mm256_add_epi32(rowA, colA), ba = _mm256_add_epi32(rowA, colB);
    const __m256i ab = _mm256_add_epi32(rowB, colA), bb = _mm256_add_epi32(rowB, colB);
    for (int c = 0; c < 3; ++c) {
        const float* base = level.rgb + c;
        const __m256 pAA = _mm256_i32gather_ps(base, aa, 4), pBA = _mm256_i32gather_ps(base, ba, 4);
        const __m256 pAB = _mm256_i32gather_ps(base, ab, 4), pBB = _mm256_i32gather_ps(base, bb, 4);
        const __m256 top = _mm256_fmadd_ps(_mm256_sub_ps(pBA, pAA), fx, pAA);
        const __m256 bottom = _mm256_fmadd_ps(_mm256_sub_ps(pBB, pAB), fx, pAB);
        rgb[c] = _mm256_fmadd_ps(_mm256_sub_ps(bottom, top), fy, top);
    }
}

__attribute__((target("avx2,fma"))) void radiancex8(const float* m, const Imath::V3f& scale,
                                                    const LatLongMap::LevelPixels& level, const Imath::V3f* directions,
                                                    std::size_t count, Imath::V3f* out) {
    alignas(32) float dx[8], dy[8], dz[8];
    for (std::size_t i = 0; i < 8; ++i) {
        const Imath::V3f& d = directions[i < count ? i : 0];  // spare lanes repeat the first
        dx[i] = d.x, dy[i] = d.y, dz[i] = d.z;
    }
    const __m256 x = _mm256_load_ps(dx), y = _mm256_load_ps(dy), z = _mm256_load_ps(dz);
    __m256 o[3];  // d * M (no lambda: it would not inherit the target)
    for (int column = 0; column < 3; ++column)
        o[column] = _mm256_fmadd_ps(z, _mm256_set1_ps(m[6 + column]),
                                    _mm256_fmadd_ps(y, _mm256_set1_ps(m[3 + column]),
                                                    _mm256_mul_ps(x, _mm256_set1_ps(m[column]))));
    const __m256 ox = o[0], oy = o[1], oz = o[2];
    const __m256 horizontal = _mm256_sqrt_ps(_mm256_fmadd_ps(ox, ox, _mm256_mul_ps(oz, oz)));
    const __m256 theta = atan2x8(oy, horizontal), phi = atan2x8(ox, oz);
    const __m256 inversePi = _mm256_set1_ps(float(1.0 / std::numbers::pi)), half = _mm256_set1_ps(0.5f);
    const __m256 u = _mm256_mul_ps(half, _mm256_fnmadd_ps(phi, inversePi, _mm256_set1_ps(1.0f)));
    const __m256 v = _mm256_fnmadd_ps(theta, inversePi, half);
    __m256 rgb[3];
    bilinearx8(level, u, v, rgb);
    alignas(32) float r[8], g[8], b[8];
    _mm256_store_ps(r, _mm256_mul_ps(rgb[0], _mm256_set1_ps(scale.x)));
    _mm256_store_ps(g, _mm256_mul_ps(rgb[1], _mm256_set1_ps(scale.y)));
    _mm256_store_ps(b, _mm256_mul_ps(rgb[2], _mm256_set1_ps(scale.z)));
    for (std::size_t i = 0; i < count; ++i) out[i] = Imath::V3f(r[i], g[i], b[i]);
}

bool cpuHasSimdKernel() { return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"); }
#else
bool cpuHasSimdKernel() { return false; }
#endif

}  // namespace

DomeLookup::DomeLookup(std::shared_ptr<const LatLongMap> map, const Imath::M33d& domeFromWorld, const Imath::V3f& scale,
                       bool simd)
    : map_(std::move(map)), scale_(scale), simd_(simd && cpuHasSimdKernel()) {
    if (!map_) throw Error("dome lookup: no lat-long map");
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) domeFromWorld_[r * 3 + c] = float(domeFromWorld[r][c]);
}

Imath::V3f DomeLookup::radiance(const Imath::V3f& d, int level) const {
    const float* m = domeFromWorld_;
    const Imath::V3f dome(d.x * m[0] + d.y * m[3] + d.z * m[6], d.x * m[1] + d.y * m[4] + d.z * m[7],
                          d.x * m[2] + d.y * m[5] + d.z * m[8]);
    const Imath::V2f uv = latLongCoordinates(dome);
    const Imath::V3f l = map_->sampleLevel(level, uv.x, uv.y);
    return {l.x * scale_.x, l.y * scale_.y, l.z * scale_.z};
}

void DomeLookup::radiance(const Imath::V3f* directions, std::size_t count, int level, Imath::V3f* out) const {
    if (count > kLanes) throw Error("dome lookup: more than 8 directions at once");
    if (count == 0) return;
#if OPAL_DOME_LOOKUP_AVX2
    if (simd_) {
        radiancex8(domeFromWorld_, scale_, map_->levelPixels(level), directions, count, out);
        return;
    }
#endif
    for (std::size_t i = 0; i < count; ++i) out[i] = radiance(directions[i], level);
}

}  // namespace opal
