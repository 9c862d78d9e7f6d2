// DomeLookup: the vectorized kernel against the portable path, and the portable path
// against the map looked up at libm's exact coordinates.
#include "delegate/image/dome_lookup.h"

#include "schema/error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace opal {
namespace {

std::shared_ptr<LatLongMap> randomMap(int width, int height, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> value(0.0f, 4.0f);
    std::vector<float> rgb(std::size_t(width) * height * 3);
    for (float& v : rgb) v = value(rng);
    return std::make_shared<LatLongMap>(width, height, std::move(rgb));
}

std::vector<Imath::V3f> randomDirections(std::size_t count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<float> normal;
    std::vector<Imath::V3f> d(count);
    for (Imath::V3f& v : d) v = Imath::V3f(normal(rng), normal(rng), normal(rng)) * 3.0f;  // any length
    // The axes and the seam (-Z, where u wraps) exactly.
    d[0] = {0, 0, -1}, d[1] = {0, 1, 0}, d[2] = {0, -1, 0}, d[3] = {1, 0, 0}, d[4] = {-1e-7f, 0, -1};
    return d;
}

Imath::M33d rotation() {
    Imath::M44d m;
    m.setAxisAngle(Imath::V3d(0.2, 1.0, -0.4).normalized(), 0.7);
    return Imath::M33d(m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]);
}

TEST(DomeLookup, VectorizedKernelMatchesThePortablePath) {
    const auto map = randomMap(64, 32, 1);
    const DomeLookup simd(map, rotation(), Imath::V3f(1.0f, 0.5f, 2.0f), true);
    const DomeLookup portable(map, rotation(), Imath::V3f(1.0f, 0.5f, 2.0f), false);
    if (!simd.usesSimd()) GTEST_SKIP() << "this CPU has no AVX2 + FMA";
    EXPECT_FALSE(portable.usesSimd());
    const std::vector<Imath::V3f> directions = randomDirections(4000, 2);
    for (int level : {0, 2, map->levels() - 1})
        for (std::size_t first = 0; first + 8 <= directions.size(); first += 8)
            for (std::size_t count : {std::size_t(8), std::size_t(3)}) {  // whole and partial blocks
                Imath::V3f a[8], b[8];
                simd.radiance(directions.data() + first, count, level, a);
                portable.radiance(directions.data() + first, count, level, b);
                for (std::size_t i = 0; i < count; ++i)
                    // Values up to 8; FMA rounding moves texel positions by ulps, and random
                    // neighbouring texels differ by up to 4: measured at most 2e-5.
                    ASSERT_LT((a[i] - b[i]).length(), 1e-4f) << directions[first + i] << " level " << level;
            }
}

TEST(DomeLookup, PortablePathIsTheMapAtTheExactCoordinates) {
    // A smooth map, so that the float atan2's 1e-5 rad shows as a small difference.
    std::vector<float> rgb;
    const int width = 256, height = 128;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Imath::V3d d = LatLongMap::direction((x + 0.5) / width, (y + 0.5) / height);
            rgb.insert(rgb.end(), {float(2.0 + d.y), float(1.0 + 0.5 * d.x), float(1.5 + 0.5 * d.z)});
        }
    const auto map = std::make_shared<LatLongMap>(width, height, std::move(rgb));
    const Imath::M33d r = rotation();
    const DomeLookup lookup(map, r, Imath::V3f(1.0f), false);
    for (const Imath::V3f& d : randomDirections(2000, 3)) {
        const Imath::V2d uv = LatLongMap::coordinates(Imath::V3d(d) * r);
        const Imath::V3f expected = map->sampleLevel(0, float(uv.x), float(uv.y));
        ASSERT_LT((lookup.radiance(d, 0) - expected).length(), 1e-4f) << d;
    }
}

TEST(DomeLookup, RejectsMoreThanEightDirections) {
    const DomeLookup lookup(randomMap(8, 4, 4), Imath::M33d(), Imath::V3f(1.0f));
    const std::vector<Imath::V3f> directions(9, Imath::V3f(0, 0, 1));
    std::vector<Imath::V3f> out(9);
    EXPECT_THROW(lookup.radiance(directions.data(), 9, 0, out.data()), Error);
    EXPECT_THROW(DomeLookup(nullptr, Imath::M33d(), Imath::V3f(1.0f)), Error);
}

}  // namespace
}  // namespace opal
