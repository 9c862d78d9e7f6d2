// The sparse maps the light sums (sparse_field_maps.h) against the lookup's own
// interpolation and Haar synthesis (ShadowFieldLookup::incidentRadiance) at the decode
// face size, at random points through the field and inside its inner shell.
#include "delegate/relight/sparse_field_maps.h"
#include "tests/fieldlight/field_fixture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace opal {
namespace {

TEST(SparseFieldMaps, WeightedSumsMatchTheLookupsSynthesis) {
    const LoadedShadowField& f = *test::sphereField().loaded;
    const std::uint32_t size = f.layout.faceSize();
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    double largest = 0.0, worst = 0.0;
    for (int i = 0; i < 200; ++i) {
        Imath::V3d d(u(random), u(random), u(random));
        if (d.length() < 1e-3) continue;
        const double r = f.field.radii.front() * 0.5 + (f.field.radii.back() - f.field.radii.front() * 0.5) *
                                                            (0.5 + 0.5 * u(random));
        const Imath::V3d p = f.field.centre + d.normalized() * r;
        const std::vector<Imath::V3f> expected = f.lookup.incidentRadiance(p, size);
        std::vector<Imath::V3f> sum(expected.size(), Imath::V3f(0.0f));
        const FieldStencil stencil = f.lookup.stencil(p);
        for (std::uint32_t m = 0; m < stencil.count; ++m) {
            const auto texels = f.maps.texels(stencil.maps[m].map);
            const auto terms = f.maps.terms(stencil.maps[m].map);
            ASSERT_TRUE(std::is_sorted(texels.begin(), texels.end()));
            for (std::size_t j = 0; j < texels.size(); ++j)
                sum[texels[j]] += Imath::V3f(terms[j][0], terms[j][1], terms[j][2]) * float(stencil.maps[m].weight);
        }
        for (std::size_t k = 0; k < sum.size(); ++k)
            for (int c = 0; c < 3; ++c) {
                largest = std::max(largest, double(expected[k][c]));
                worst = std::max(worst, std::abs(double(std::max(0.0f, sum[k][c])) - expected[k][c]));
            }
    }
    ASSERT_GT(largest, 0.0);
    EXPECT_LE(worst, 1e-5 * largest);
}

}  // namespace
}  // namespace opal
