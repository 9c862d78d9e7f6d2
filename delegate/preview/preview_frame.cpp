#include "delegate/preview/preview_frame.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace opal::preview {
namespace {

PreviewPixel shade(const PreviewScene& scene, const Ray& ray, const RayHit& hit, const FrameLook& look) {
    PreviewPixel pixel;
    const Imath::V3f normal = scene.shadingNormal(hit);
    const Imath::V3f toCamera = -ray.direction().normalized();
    const Rgb color = look.shading == Shading::Lambert
                          ? headlightLambert(scene.mesh(hit.prim).albedo, look.headlight, normal, toCamera)
                          : normalColor(normal);
    for (int c = 0; c < 3; ++c) pixel.color[c] = float(color[c]);
    pixel.color[3] = 1.0f;
    pixel.normal[0] = normal.x;
    pixel.normal[1] = normal.y;
    pixel.normal[2] = normal.z;
    pixel.depth = hit.t;  // the camera's rays have a view-space z of -1: t is the depth
    pixel.primId = float(scene.mesh(hit.prim).primId);
    return pixel;
}

}  // namespace

std::vector<PreviewPixel> renderFrame(const PreviewScene& scene, const CameraView& view, const FrameLook& look) {
    const int width = view.width(), height = view.height();
    std::vector<PreviewPixel> pixels(std::size_t(width) * height);
    if (scene.rays().meshCount() == 0) return pixels;
    const CameraView::PixelRect seen = view.pixelBounds(scene.rays().bounds());
    tbb::parallel_for(tbb::blocked_range<int>(seen.y0, seen.y1), [&](const tbb::blocked_range<int>& rows) {
        // A row's rays traced together: neighbours' rays are coherent (ray_scene.h's packets).
        std::vector<Ray> rays(std::size_t(seen.x1 - seen.x0));
        std::vector<std::optional<RayHit>> hits(rays.size());
        for (int y = rows.begin(); y < rows.end(); ++y) {
            for (int x = seen.x0; x < seen.x1; ++x) rays[std::size_t(x - seen.x0)] = view.ray(x + 0.5, y + 0.5);
            scene.rays().intersectCoherent(rays, hits);
            for (int x = seen.x0; x < seen.x1; ++x)
                if (const std::optional<RayHit>& hit = hits[std::size_t(x - seen.x0)])
                    pixels[std::size_t(y) * width + x] = shade(scene, rays[std::size_t(x - seen.x0)], *hit, look);
        }
    });
    return pixels;
}

}  // namespace opal::preview
