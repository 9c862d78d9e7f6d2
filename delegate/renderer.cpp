#include "delegate/renderer.h"

#include "delegate/specular.h"
#include "schema/scatter/dipole.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace opal {

namespace {

// Shadow rays start this fraction of the scene's extent off the surface, as the
// irradiance's shadow rays do (mesh_irradiance.cpp).
constexpr double kShadowOffset = 1e-4;

const std::array<hd::Token, 8> Aovs = {hd::Aov::Color,  hd::Aov::Subsurface, hd::Aov::Specular, hd::Aov::Irradiance,
                                       hd::Aov::Normal, hd::Aov::Depth,      hd::Aov::PrimId,   hd::Aov::Alpha};

struct Pixel {
    Imath::V3f subsurface{0.0f}, specular{0.0f}, irradiance{0.0f}, normal{0.0f}, background{0.0f};
    float depth = std::numeric_limits<float>::infinity();
    float primId = -1.0f;
    float alpha = 0.0f;
    bool hit = false;
};

Imath::V3f domeRadiance(const DomeView& dome, const Imath::V3d& worldDirection, double footprint) {
    const Imath::V2d uv = LatLongMap::coordinates(worldDirection * dome.worldToDome);
    const Imath::V3f l = dome.map->sample(uv.x, uv.y, footprint);
    return {l.x * float(dome.scale.x), l.y * float(dome.scale.y), l.z * float(dome.scale.z)};
}

// sum_j b_j value[v_j] over the hit triangle's vertices, RGB.
Imath::V3f interpolate(const std::vector<float>& values, const std::array<std::uint32_t, 3>& v,
                       const std::array<float, 3>& b) {
    Imath::V3f sum(0.0f);
    for (int j = 0; j < 3; ++j) {
        const float* p = values.data() + 3 * std::size_t(v[j]);
        sum += Imath::V3f(p[0], p[1], p[2]) * b[j];
    }
    return sum;
}

Imath::V3f specularLayer(const Frame& frame, const MeshShading& mesh, const Imath::V3d& p, const Imath::V3d& n,
                         const Imath::V3d& ng, const Imath::V3d& wo) {
    const double alpha = ggxAlpha(mesh.roughness);
    const double offset = kShadowOffset * frame.rays->extent();
    Imath::V3d sum(0.0);
    for (const AnalyticLight& light : frame.lights) {
        const std::optional<Incidence> in = light.incidence(p);
        if (!in || ng.dot(in->toLight) <= 0.0) continue;  // no light, or below the surface
        const double f = ggxReflectance(n, wo, in->toLight, alpha, mesh.eta);
        if (f <= 0.0) continue;
        Ray shadow;
        shadow.origin = Imath::V3f(p + ng * offset);
        shadow.direction = Imath::V3f(in->toLight);
        shadow.tNear = 0.0f;
        shadow.tFar = std::isinf(in->distance) ? std::numeric_limits<float>::infinity()
                                               : float(in->distance * (1.0 - 1e-4));
        if (frame.rays->occluded(shadow)) continue;
        sum += Imath::V3d(in->normalIrradiance.x, in->normalIrradiance.y, in->normalIrradiance.z) * f;
    }
    Imath::V3f result(sum);
    if (!frame.domes.empty()) {
        const double fr = fresnelReflectance(mesh.eta, n.dot(wo));
        const Imath::V3d r = reflect(wo, n);
        const double footprint = reflectionFootprint(alpha);
        for (const DomeView& dome : frame.domes) result += domeRadiance(dome, r, footprint) * float(fr);
    }
    return result;
}

Pixel shade(const Frame& frame, const CameraView& camera, const RenderOptions& options, int x, int y) {
    Pixel pixel;
    const Ray ray = camera.ray(x + 0.5, y + 0.5);
    const Imath::V3d direction = Imath::V3d(ray.direction).normalized();
    const std::optional<RayHit> hit = frame.rays ? frame.rays->intersect(ray) : std::nullopt;
    if (!hit) {
        if (options.transparentBackground) return pixel;
        for (const DomeView& dome : frame.domes) {
            if (!dome.visibleToCamera) continue;
            pixel.background += domeRadiance(dome, direction, camera.pixelAngle());
            pixel.alpha = 1.0f;
        }
        return pixel;
    }
    const MeshShading& mesh = *frame.meshes[hit->prim];
    const std::array<std::uint32_t, 3> v = frame.rays->triangleVertices(hit->prim, hit->triangle);
    const std::array<float, 3> b = {1.0f - hit->u - hit->v, hit->u, hit->v};
    const Imath::V3d p = Imath::V3d(ray.origin) + Imath::V3d(ray.direction) * double(hit->t);
    const Imath::V3d wo = -direction;
    Imath::V3d ng = Imath::V3d(hit->geometricNormal).normalized();
    if (ng.dot(wo) < 0.0) ng = -ng;  // seen from behind: offsets go to the viewer's side
    Imath::V3d n = ng;
    const std::vector<Imath::V3f>& normals = mesh.asset->mesh.normals;
    if (normals.size() == mesh.asset->mesh.points.size()) {
        const Imath::V3f object = normals[v[0]] * b[0] + normals[v[1]] * b[1] + normals[v[2]] * b[2];
        const Imath::V3d world = Imath::V3d(object * mesh.normalToWorld);
        if (world.length() > 0.0) n = world.normalized();
    }
    const double muO = std::max(0.0, n.dot(wo));
    pixel.subsurface = interpolate(mesh.vertexRadiance, v, b) * float(fresnelTransmittance(mesh.eta, muO));
    pixel.irradiance = interpolate(mesh.vertexIrradiance, v, b);
    if (options.specular && mesh.specular) pixel.specular = specularLayer(frame, mesh, p, n, ng, wo);
    pixel.normal = Imath::V3f(n);
    pixel.depth = hit->t;
    pixel.primId = float(mesh.primId);
    pixel.alpha = 1.0f;
    pixel.hit = true;
    return pixel;
}

void store(float* target, int channels, std::size_t index, const float* values) {
    if (target) std::copy_n(values, channels, target + index * std::size_t(channels));
}

void write(const AovTargets& t, std::size_t index, const Pixel& p) {
    const Imath::V3f color = p.hit ? p.subsurface + p.specular : p.background;
    const float rgba[4] = {color.x, color.y, color.z, p.alpha};
    store(t.color, 4, index, rgba);
    store(t.subsurface, 3, index, &p.subsurface.x);
    store(t.specular, 3, index, &p.specular.x);
    store(t.irradiance, 3, index, &p.irradiance.x);
    store(t.normal, 3, index, &p.normal.x);
    store(t.depth, 1, index, &p.depth);
    store(t.primId, 1, index, &p.primId);
    store(t.alpha, 1, index, &p.alpha);
}

}  // namespace

std::span<const hd::Token> supportedAovs() { return Aovs; }

int aovChannelCount(const hd::Token& aov) {
    if (aov == hd::Aov::Color) return 4;
    if (aov == hd::Aov::Subsurface || aov == hd::Aov::Specular || aov == hd::Aov::Irradiance || aov == hd::Aov::Normal)
        return 3;
    if (aov == hd::Aov::Depth || aov == hd::Aov::PrimId || aov == hd::Aov::Alpha) return 1;
    return 0;
}

void renderFrame(const Frame& frame, const CameraView& camera, const RenderOptions& options, const AovTargets& targets) {
    const int width = camera.width(), height = camera.height();
    const int tile = std::max(1, options.tileSize);
    const int tilesX = (width + tile - 1) / tile, tilesY = (height + tile - 1) / tile;
    tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY), [&](const tbb::blocked_range<int>& range) {
        for (int t = range.begin(); t != range.end(); ++t) {
            const int x0 = (t % tilesX) * tile, y0 = (t / tilesX) * tile;
            for (int y = y0; y < std::min(y0 + tile, height); ++y)
                for (int x = x0; x < std::min(x0 + tile, width); ++x)
                    write(targets, std::size_t(y) * width + x, shade(frame, camera, options, x, y));
        }
    });
}

}  // namespace opal
