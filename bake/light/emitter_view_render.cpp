#include "bake/light/emitter_view_render.h"

#include "schema/asset/array_codec.h"
#include "schema/asset/cube_map.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace opal {
namespace {

constexpr int kRaysPerSide = 4;

void renderView(const EmitterScene& scene, const Imath::V3d& v, std::uint32_t size, float* out) {
    const BoundingSphere& b = scene.bounds();
    Imath::V3d right, up;
    viewAxes(v, right, up);
    const Imath::V3d back = b.centre + v * (2.0 * b.radius);  // outside the bounding sphere
    const double step = 2.0 * b.radius / size;
    const float weight = 1.0f / (kRaysPerSide * kRaysPerSide);
    for (std::uint32_t j = 0; j < size; ++j)
        for (std::uint32_t i = 0; i < size; ++i) {
            Imath::V3f sum(0.0f);
            for (int sy = 0; sy < kRaysPerSide; ++sy)
                for (int sx = 0; sx < kRaysPerSide; ++sx) {
                    const double x = -b.radius + (i + (sx + 0.5) / kRaysPerSide) * step;
                    const double y = -b.radius + (j + (sy + 0.5) / kRaysPerSide) * step;
                    const Ray ray(Imath::V3f(back + right * x + up * y), Imath::V3f(-v), 0.0f, float(4.0 * b.radius));
                    sum += scene.radiance(ray, scene.rays().intersect(ray));
                }
            float* p = out + 3 * (std::size_t(j) * size + i);
            p[0] = sum.x * weight;
            p[1] = sum.y * weight;
            p[2] = sum.z * weight;
        }
}

}  // namespace

EmitterViews renderEmitterViews(const EmitterScene& scene, std::uint32_t viewFaceSize, std::uint32_t imageSize) {
    EmitterViews views;
    views.directionFaceSize = viewFaceSize;
    views.imageSize = imageSize;
    views.radiance.assign(views.values(), 0.0f);
    const CubeMapLayout directions(viewFaceSize);
    const std::size_t perView = 3 * std::size_t(imageSize) * imageSize;
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, views.views()), [&](const auto& range) {
        for (std::uint32_t k = range.begin(); k != range.end(); ++k)
            renderView(scene, Imath::V3d(directions.direction(k)), imageSize, views.radiance.data() + k * perView);
    });
    roundToHalfPlanes(views.radiance);
    return views;
}

}  // namespace opal
