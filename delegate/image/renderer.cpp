#include "delegate/image/renderer.h"

#include "delegate/image/dome_lookup.h"
#include "delegate/image/fresnel_table.h"
#include "delegate/image/sample_pattern.h"

#include "delegate/image/specular.h"
#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#if defined(__SSE2__)
#include <emmintrin.h>  // _mm_stream_ps, _mm_sfence: SSE2, in every x86-64
#define OPAL_STREAMING_STORES 1
#else
#define OPAL_STREAMING_STORES 0
#endif

#include <algorithm>
#include <atomic>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <cstdint>

namespace opal {

namespace {

// Shadow rays start this fraction of the scene's extent off the surface, as the
// irradiance's shadow rays do (mesh_irradiance.cpp).
constexpr double kShadowOffset = 1e-4;

// Pixels are shaded in blocks of kBlockWidth x kBlockHeight neighbours: their primary rays
// are one Embree packet, their shadow rays toward one light another (RayScene's coherent
// queries, about twice as fast as one ray at a time).
constexpr int kBlockWidth = 4, kBlockHeight = 4;
constexpr int kBlockPixels = kBlockWidth * kBlockHeight;
static_assert(kBlockPixels == int(RayScene::kPacketSize));

struct Pixel {
    Imath::V3f subsurface{0.0f}, specular{0.0f}, emission{0.0f}, irradiance{0.0f}, normal{0.0f}, background{0.0f};
    float depth = std::numeric_limits<float>::infinity();
    float primId = -1.0f;
    float alpha = 0.0f;
    bool hit = false;
};

// What shading reads of one mesh, looked up once per frame instead of once per pixel.
struct MeshContext {
    const MeshShading* shading = nullptr;
    std::span<const std::uint32_t> triangles;  // 3 render-mesh vertices per ray-scene triangle
    const Imath::V3f* normals = nullptr;       // per vertex, object space; null: geometric normals
    double alpha = 0.0;                        // ggxAlpha(roughness)
    double footprint = 0.0;                    // reflectionFootprint(alpha)
    bool specular = false;                     // the GGX layer is on (render setting and material)
    std::optional<FresnelTable> fresnel;       // F_t(shading->eta, .)
};

// The frame as the pixel loop reads it.
struct FrameContext {
    const Frame& frame;
    const RenderOptions& options;
    const CameraView& camera;
    std::vector<MeshContext> meshes;  // by ray-scene prim number
    std::vector<DomeLookup> domes;    // frame.domes, as the pixel loop looks them up
    std::vector<int> backgroundLevels;  // per dome: its pyramid level for one pixel (-1: not visible)
    std::vector<const ShadowFieldLight*> emitters;  // frame.emitters
    double shadowOffset = 0.0;        // kShadowOffset * the scene's extent
    CameraView::PixelRect scene;      // where primary rays may hit (empty: no meshes)
    bool irradiance = false;          // the irradiance AOV is bound: interpolate E at hits
};

FrameContext frameContext(const Frame& frame, const CameraView& camera, const RenderOptions& options,
                          const AovTargets& targets) {
    FrameContext context{frame, options, camera, {}, {}, {}, {}, 0.0, {}, false};
    context.irradiance = targets[std::size_t(hd::AovId::Irradiance)] != nullptr;
    for (const DomeView& dome : frame.domes) {
        context.domes.emplace_back(dome.map, dome.domeFromWorld, Imath::V3f(dome.scale.x, dome.scale.y, dome.scale.z));
        context.backgroundLevels.push_back(dome.visibleToCamera ? context.domes.back().levelFor(camera.pixelAngle()) : -1);
    }
    Imath::Box3f bounds;  // what primary rays can meet: the meshes and the emitters
    for (const auto& emitter : frame.emitters) {
        context.emitters.push_back(emitter.get());
        const Imath::V3f centre(emitter->centre()), reach(float(emitter->emitterRadius()));
        bounds.extendBy(Imath::Box3f(centre - reach, centre + reach));
    }
    if (!frame.rays) {
        if (!bounds.isEmpty()) context.scene = camera.pixelBounds(bounds);
        return context;
    }
    context.shadowOffset = kShadowOffset * frame.rays->extent();
    bounds.extendBy(frame.rays->bounds());
    context.scene = camera.pixelBounds(bounds);
    for (std::size_t prim = 0; prim < frame.meshes.size(); ++prim) {
        const MeshShading& shading = *frame.meshes[prim];
        MeshContext mesh;
        mesh.fresnel.emplace(shading.eta);
        mesh.shading = &shading;
        mesh.triangles = frame.rays->triangles(std::uint32_t(prim));
        const RenderMesh& renderMesh = shading.asset->mesh;
        if (renderMesh.normals.size() == renderMesh.points.size()) mesh.normals = renderMesh.normals.data();
        mesh.alpha = ggxAlpha(shading.roughness);
        mesh.footprint = reflectionFootprint(mesh.alpha);
        mesh.specular = options.specular && shading.specular;
        context.meshes.push_back(mesh);
    }
    return context;
}

// v / |v| with one division.
Imath::V3d unit(const Imath::V3d& v) { return v * (1.0 / v.length()); }

// sum_j b_j value[v_j] over the hit triangle's vertices, RGB.
Imath::V3f interpolate(const std::vector<float>& values, const std::uint32_t* v, const float* b) {
    Imath::V3f sum(0.0f);
    for (int j = 0; j < 3; ++j) {
        const float* p = values.data() + 3 * std::size_t(v[j]);
        sum += Imath::V3f(p[0], p[1], p[2]) * b[j];
    }
    return sum;
}

// Where a primary ray hit a mesh, as the specular layer needs it (world space, unit vectors).
struct Surface {
    const MeshContext* mesh = nullptr;  // null: no specular layer here (a miss, or switched off)
    Imath::V3d p, n, ng, wo;            // point, shading normal, geometric normal toward wo, toward the viewer
    double fresnelReflectance = 0.0;    // F_r(eta, n.wo) = 1 - F_t(eta, n.wo)
};

struct Block {
    int count = 0;
    int step = 1;                   // pixels per sample side: 1, or the draft's N (an N x N cell a sample)
    Imath::V2f offset{0.5f, 0.5f};  // the pass's sample position inside each pixel (or cell)
    std::array<int, kBlockPixels> x{}, y{};
    std::array<Ray, kBlockPixels> rays;
    std::array<std::optional<RayHit>, kBlockPixels> hits;
    std::array<Surface, kBlockPixels> surfaces;
    std::array<Pixel*, kBlockPixels> pixels{};  // where each sample is shaded: its place in the tile
};

// dome.radiance for any count, DomeLookup::kLanes at a time.
void lookUp(const DomeLookup& dome, const Imath::V3f* directions, std::size_t count, int level, Imath::V3f* out) {
    for (std::size_t first = 0; first < count; first += DomeLookup::kLanes)
        dome.radiance(directions + first, std::min(DomeLookup::kLanes, count - first), level, out + first);
}

// The domes visible to the camera behind the pixels whose rays missed, one lookup call per
// dome for the block.
void background(const FrameContext& context, Block& block) {
    if (context.options.transparentBackground) return;
    std::array<Imath::V3f, kBlockPixels> directions;
    std::array<int, kBlockPixels> pixelOf{};
    std::size_t count = 0;
    for (int i = 0; i < block.count; ++i)
        if (!block.hits[i]) {
            directions[count] = block.rays[i].direction();
            pixelOf[count++] = i;
        }
    if (count == 0) return;
    std::array<Imath::V3f, kBlockPixels> radiance;
    for (std::size_t d = 0; d < context.domes.size(); ++d) {
        if (context.backgroundLevels[d] < 0) continue;
        lookUp(context.domes[d], directions.data(), count, context.backgroundLevels[d], radiance.data());
        for (std::size_t k = 0; k < count; ++k) {
            Pixel& pixel = *block.pixels[pixelOf[k]];
            pixel.background += radiance[k];
            pixel.alpha = 1.0f;
        }
    }
}

// Everything but the specular layer: subsurface = F_t(eta, n.w_o) sum_j b_j L(v_j), E, n, depth.
Surface shadeSurface(const FrameContext& context, const Ray& ray, const RayHit& hit, Pixel& pixel) {
    const MeshContext& mesh = context.meshes[hit.prim];
    const MeshShading& shading = *mesh.shading;
    const std::uint32_t* v = mesh.triangles.data() + 3 * std::size_t(hit.triangle);
    const float b[3] = {1.0f - hit.u - hit.v, hit.u, hit.v};
    Surface s;
    s.p = Imath::V3d(ray.origin()) + Imath::V3d(ray.direction()) * double(hit.t);
    s.wo = -unit(Imath::V3d(ray.direction()));
    s.ng = unit(Imath::V3d(hit.geometricNormal));
    if (s.ng.dot(s.wo) < 0.0) s.ng = -s.ng;  // seen from behind: offsets go to the viewer's side
    s.n = s.ng;
    if (mesh.normals) {
        const Imath::V3f object = mesh.normals[v[0]] * b[0] + mesh.normals[v[1]] * b[1] + mesh.normals[v[2]] * b[2];
        const Imath::V3d world = Imath::V3d(object * shading.normalToWorld);
        if (world.length() > 0.0) s.n = unit(world);
    }
    const double muO = std::max(0.0, s.n.dot(s.wo));
    const double transmittance = mesh.fresnel->transmittance(muO);
    s.fresnelReflectance = 1.0 - transmittance;  // fresnelReflectance(eta, n.wo): F_t clamps the same way
    pixel.subsurface = interpolate(*shading.vertexRadiance, v, b) * float(transmittance);
    if (context.irradiance) pixel.irradiance = interpolate(*shading.vertexIrradiance, v, b);
    pixel.normal = Imath::V3f(s.n);
    pixel.depth = hit.t;
    pixel.primId = float(shading.primId);
    pixel.alpha = 1.0f;
    pixel.hit = true;
    if (mesh.specular) s.mesh = &mesh;
    return s;
}

// sum over the analytic lights of f_s (n.l) E_perp V, V by one packet of shadow rays per light.
void analyticSpecular(const FrameContext& context, const Block& block, std::array<Imath::V3d, kBlockPixels>& sums) {
    std::array<Ray, kBlockPixels> shadows;
    std::array<Imath::V3d, kBlockPixels> unshadowed;
    std::array<int, kBlockPixels> pixelOf{};
    std::array<std::uint8_t, kBlockPixels> blocked{};
    for (const AnalyticLight& light : context.frame.lights) {
        std::size_t count = 0;
        for (int i = 0; i < block.count; ++i) {
            const Surface& s = block.surfaces[i];
            if (!s.mesh) continue;
            const std::optional<Incidence> in = light.incidence(s.p);
            if (!in || s.ng.dot(in->toLight) <= 0.0) continue;  // no light, or below the surface
            const double f = ggxReflectance(s.n, s.wo, in->toLight, s.mesh->alpha, *s.mesh->fresnel);
            if (f <= 0.0) continue;
            const float far = std::isinf(in->distance) ? std::numeric_limits<float>::infinity()
                                                       : float(in->distance * (1.0 - 1e-4));
            shadows[count] = Ray(Imath::V3f(s.p + s.ng * context.shadowOffset), Imath::V3f(in->toLight), 0.0f, far);
            unshadowed[count] = Imath::V3d(in->normalIrradiance.x, in->normalIrradiance.y, in->normalIrradiance.z) * f;
            pixelOf[count++] = i;
        }
        if (count == 0) continue;
        context.frame.rays->occludedCoherent(std::span(shadows).first(count), std::span(blocked).first(count));
        for (std::size_t k = 0; k < count; ++k)
            if (!blocked[k]) sums[pixelOf[k]] += unshadowed[k];
    }
}

// The domes' reflection F_r(eta, n.v) L_dome(reflect(v, n), footprint) at the block's
// specular surfaces: one lookup call per dome and run of surfaces of one mesh.
void domeReflections(const FrameContext& context, Block& block) {
    if (context.domes.empty()) return;
    std::array<Imath::V3f, kBlockPixels> directions, radiance;
    std::array<int, kBlockPixels> pixelOf{};
    for (int first = 0; first < block.count;) {
        const MeshContext* mesh = block.surfaces[first].mesh;
        if (!mesh) {
            ++first;
            continue;
        }
        std::size_t count = 0;
        int i = first;
        for (; i < block.count && (block.surfaces[i].mesh == mesh || !block.surfaces[i].mesh); ++i) {
            const Surface& s = block.surfaces[i];
            if (!s.mesh) continue;
            directions[count] = Imath::V3f(reflect(s.wo, s.n));
            pixelOf[count++] = i;
        }
        first = i;
        for (const DomeLookup& dome : context.domes) {
            lookUp(dome, directions.data(), count, dome.levelFor(mesh->footprint), radiance.data());
            for (std::size_t k = 0; k < count; ++k)
                block.pixels[pixelOf[k]]->specular += radiance[k] * float(block.surfaces[pixelOf[k]].fresnelReflectance);
        }
    }
}

// The specular layer (specular.h): the analytic lights, then the domes' reflection
// F_r(eta, n.v) L_dome(reflect(v, n), footprint).
void shadeSpecular(const FrameContext& context, Block& block) {
    std::array<Imath::V3d, kBlockPixels> sums;
    sums.fill(Imath::V3d(0.0));
    analyticSpecular(context, block, sums);
    for (int i = 0; i < block.count; ++i) {
        const Surface& s = block.surfaces[i];
        if (!s.mesh) continue;
        block.pixels[i]->specular = Imath::V3f(sums[i]);
    }
    domeReflections(context, block);
}

// The hit triangles' vertex data (normal, radiance, irradiance: three arrays of megabytes,
// read at random) requested for the whole block before any pixel is shaded, so that the
// memory latencies overlap instead of adding up (720p benchmark frame: medians 45-50 -> 44 ms).
void prefetchVertices(const FrameContext& context, const Block& block) {
    for (int i = 0; i < block.count; ++i) {
        const std::optional<RayHit>& hit = block.hits[i];
        if (!hit) continue;
        const MeshContext& mesh = context.meshes[hit->prim];
        const std::uint32_t* v = mesh.triangles.data() + 3 * std::size_t(hit->triangle);
        for (int j = 0; j < 3; ++j) {
            if (mesh.normals) __builtin_prefetch(mesh.normals + v[j]);
            __builtin_prefetch(mesh.shading->vertexRadiance->data() + 3 * std::size_t(v[j]));
            if (context.irradiance) __builtin_prefetch(mesh.shading->vertexIrradiance->data() + 3 * std::size_t(v[j]));
        }
    }
}

// The emitters each ray passes in front of whatever it hit: additive emission, and the
// nearest emitter's depth and primId where one is in front (emitter k is prim
// meshes.size() + k).
void shadeEmitters(const FrameContext& context, Block& block) {
    for (int i = 0; i < block.count; ++i) {
        const Ray& ray = block.rays[i];
        const double length = Imath::V3d(ray.direction()).length();
        if (!(length > 0.0)) continue;
        const Imath::V3d o(ray.origin()), d = Imath::V3d(ray.direction()) / length;
        Pixel& pixel = *block.pixels[i];
        const double hitT = block.hits[i] ? double(block.hits[i]->t) : std::numeric_limits<double>::infinity();
        double nearest = hitT;
        for (std::size_t k = 0; k < context.emitters.size(); ++k) {
            double t = 0.0;
            const Imath::V3f radiance = context.emitters[k]->emitted(o, d, t);
            const double rayT = t / length;  // in the primary ray's parameter, as hit.t
            if (radiance.x + radiance.y + radiance.z <= 0.0f || !(rayT < hitT)) continue;
            pixel.emission += radiance;
            pixel.alpha = 1.0f;
            if (rayT < nearest) {
                nearest = rayT;
                pixel.depth = float(rayT);
                pixel.primId = float(context.meshes.size() + k);
            }
        }
    }
}

void shadeBlock(const FrameContext& context, Block& block) {
    for (int i = 0; i < block.count; ++i) {
        block.rays[i] = context.camera.ray(block.x[i] + block.offset.x, block.y[i] + block.offset.y);
        *block.pixels[i] = Pixel{};
        block.surfaces[i] = Surface{};
    }
    const std::span<const Ray> rays = std::span(block.rays).first(std::size_t(block.count));
    const std::span<std::optional<RayHit>> hits = std::span(block.hits).first(std::size_t(block.count));
    // Blocks outside the scene's projected bounds miss everything: no rays traced.
    const int x0 = block.x[0], y0 = block.y[0];
    const int x1 = block.x[block.count - 1] + block.step, y1 = block.y[block.count - 1] + block.step;
    if (context.frame.rays && context.scene.overlaps(x0, y0, x1, y1))
        context.frame.rays->intersectCoherent(rays, hits);
    else
        std::fill(hits.begin(), hits.end(), std::nullopt);
    prefetchVertices(context, block);
    bool specular = false;
    for (int i = 0; i < block.count; ++i) {
        if (!hits[i]) continue;
        block.surfaces[i] = shadeSurface(context, rays[i], *hits[i], *block.pixels[i]);
        specular = specular || block.surfaces[i].mesh;
    }
    background(context, block);
    if (!context.emitters.empty()) shadeEmitters(context, block);
    if (specular) shadeSpecular(context, block);
}

// One AOV's values at a shaded sample, in hd::aovTable's channels: a fixed count, so that
// the compiler writes them in place.
template <hd::AovId A>
void putAov(const Pixel& p, float* out) {
    using enum hd::AovId;
    const auto put = [out](auto... values) {
        int c = 0;
        ((out[c++] = values), ...);
    };
    if constexpr (A == Color) {
        const Imath::V3f c = (p.hit ? p.subsurface + p.specular : p.background) + p.emission;
        put(c.x, c.y, c.z, p.alpha);
    } else if constexpr (A == Subsurface) {
        put(p.subsurface.x, p.subsurface.y, p.subsurface.z);
    } else if constexpr (A == Specular) {
        put(p.specular.x, p.specular.y, p.specular.z);
    } else if constexpr (A == Emission) {
        put(p.emission.x, p.emission.y, p.emission.z);
    } else if constexpr (A == Irradiance) {
        put(p.irradiance.x, p.irradiance.y, p.irradiance.z);
    } else if constexpr (A == Normal) {
        put(p.normal.x, p.normal.y, p.normal.z);
    } else if constexpr (A == Depth) {
        put(p.depth);
    } else if constexpr (A == PrimId) {
        put(p.primId);
    } else {
        put(p.alpha);
    }
}

// n pixels' values of AOV `a` (channels c each) into out: the switch once per row.
template <hd::AovId A>
void putRow(const Pixel* pixels, std::size_t n, std::size_t c, float* out) {
    for (std::size_t i = 0; i < n; ++i) putAov<A>(pixels[i], out + i * c);
}

void putRow(hd::AovId aov, const Pixel* pixels, std::size_t n, std::size_t c, float* out) {
    using enum hd::AovId;
    switch (aov) {
        case Color: return putRow<Color>(pixels, n, c, out);
        case Subsurface: return putRow<Subsurface>(pixels, n, c, out);
        case Specular: return putRow<Specular>(pixels, n, c, out);
        case Emission: return putRow<Emission>(pixels, n, c, out);
        case Irradiance: return putRow<Irradiance>(pixels, n, c, out);
        case Normal: return putRow<Normal>(pixels, n, c, out);
        case Depth: return putRow<Depth>(pixels, n, c, out);
        case PrimId: return putRow<PrimId>(pixels, n, c, out);
        case Alpha: return putRow<Alpha>(pixels, n, c, out);
    }
}

// A tile's AOVs, shaded into cache and then written to the frame's buffers row by row, the
// whole tile under the buffer's tile lock (hd::RenderBuffer::writeTiles). Pass 0 replaces
// the pixels with non-temporal stores: plain stores would first read every line of the
// frame's AOVs (70 MB at 720p with every AOV) into the cache only to overwrite it. Later
// passes move each filtered AOV toward the new sample: v += (w_p / W_p)(s - v), the running
// form of sum w_i s_i / sum w_i with W_p = w_1 + ... + w_p.
// A draft (step > 1) holds one sample per step x step cell, which flush writes to each
// pixel of the cell.
class TileAovs {
public:
    TileAovs(const AovTargets& frame, int pass, int step, int tileWidth, int tileHeight)
        : frame_(frame), pass_(pass), step_(step), tileWidth_(tileWidth), pixels_(std::size_t(tileWidth) * tileHeight),
          row_(std::size_t(tileWidth) * 4), cellRow_(step > 1 ? row_.size() : 0) {}

    // The sample of tile pixel (x - x0, y - y0), or of the draft's cell holding it: shade into it.
    Pixel& pixel(int x, int y) {
        if (step_ > 1) x /= step_, y /= step_;  // two integer divisions a sample, which a pass does not need
        return pixels_[std::size_t(y) * tileWidth_ + std::size_t(x)];
    }

    // Rows [y0, y1) x columns [x0, x1) of the tile into the frame; `blend` = w_p / W_p.
    // Pass 0 writes every bound AOV, later passes the filtered ones.
    void flush(int x0, int y0, int x1, int y1, float blend) {
        for (std::size_t a = 0; a < hd::kAovCount; ++a) {
            const hd::AovDescriptor& aov = hd::aovDescriptor(hd::AovId(a));
            if (!frame_[a] || (pass_ > 0 && aov.sampling != hd::AovSampling::Filtered)) continue;
            hd::RenderBuffer& buffer = *frame_[a];
            const std::size_t c = std::size_t(aov.channelCount()), n = std::size_t(x1 - x0);
            buffer.writeTiles([&](float* target) {
                for (int y = y0; y < y1; ++y) {
                    if ((y - y0) % step_ == 0) fillRow(hd::AovId(a), (y - y0) / step_, n, c);
                    float* to = target + (std::size_t(y) * buffer.width() + x0) * c;
                    if (pass_ == 0 || blend == 1.0f)
                        streamCopy(row_.data(), to, n * c);
                    else
                        for (std::size_t i = 0; i < n * c; ++i) to[i] += blend * (row_[i] - to[i]);
                }
#if OPAL_STREAMING_STORES
                _mm_sfence();  // the streamed rows are visible before the lock is released
#endif
            });
        }
    }

private:
    // row_ = the n pixels of tile row (or draft cell row) `row`, AOV `aov`, c channels each.
    void fillRow(hd::AovId aov, int row, std::size_t n, std::size_t c) {
        const Pixel* samples = pixels_.data() + std::size_t(row) * tileWidth_;
        if (step_ == 1) return putRow(aov, samples, n, c, row_.data());
        const std::size_t step = std::size_t(step_);
        putRow(aov, samples, (n + step - 1) / step, c, cellRow_.data());
        for (std::size_t x = 0; x < n; ++x) std::copy_n(cellRow_.data() + x / step * c, c, row_.data() + x * c);
    }

    // to[0, n) = from[0, n): plain stores up to a 16-byte boundary, then 4 floats a store.
    static void streamCopy(const float* from, float* to, std::size_t n) {
        std::size_t i = 0;
#if OPAL_STREAMING_STORES
        for (; i < n && (reinterpret_cast<std::uintptr_t>(to + i) & 15u) != 0; ++i) to[i] = from[i];
        for (; i + 4 <= n; i += 4) _mm_stream_ps(to + i, _mm_loadu_ps(from + i));
#endif
        for (; i < n; ++i) to[i] = from[i];
    }

    const AovTargets& frame_;
    int pass_, step_;
    int tileWidth_;
    std::vector<Pixel> pixels_;   // the tile's samples (a draft's: its cells'), row-major
    std::vector<float> row_;      // one row of one AOV, its channels interleaved
    std::vector<float> cellRow_;  // a draft's: one row of cells of one AOV
};

// Debug builds check what a pass wrote: every radiometric AOV finite (light_emission.h keeps
// every sum in range; the relight engine refuses non-finite radiance). Tests check the same
// on Release builds through the buffers.
[[maybe_unused]] void requireFiniteRadiometric(const AovTargets& targets) {
    for (std::size_t a = 0; a < hd::kAovCount; ++a) {
        const hd::AovDescriptor& aov = hd::aovDescriptor(hd::AovId(a));
        if (!targets[a] || aov.sampling != hd::AovSampling::Filtered) continue;
        const std::span<const float> values = targets[a]->data();
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]))
                throw Error("renderer: pixel " + std::to_string(i / std::size_t(aov.channelCount())) + " of AOV " +
                            aov.name + " is not finite");
    }
}

// Pass p's sample position and its blend weight w_p / W_p (1 for passes 0 and 1).
std::pair<Imath::V2f, float> passSample(const RenderOptions& options, int pass) {
    if (pass == 0) return {Imath::V2f(0.5f, 0.5f), 1.0f};
    double total = 0.0;
    for (int p = 1; p <= pass; ++p) total += filterWeight(options.filter, samplePosition(std::uint32_t(p - 1)));
    const Imath::V2f position = samplePosition(std::uint32_t(pass - 1));
    return {position, float(filterWeight(options.filter, position) / total)};
}

}  // namespace

namespace {

// Pass `pass` (0 with `step` > 1: the draft) tile by tile: one sample per step x step cell of
// pixels, at `offset` inside the cell, written to every pixel of the cell.
bool renderSamples(const Frame& frame, const CameraView& camera, const RenderOptions& options,
                   const AovTargets& targets, int pass, int step, const std::function<bool()>& stop) {
    const FrameContext context = frameContext(frame, camera, options, targets);
    const auto [sample, blend] = passSample(options, pass);
    const Imath::V2f offset = step == 1 ? sample : Imath::V2f(0.5f * float(step));
    const int width = camera.width(), height = camera.height();
    // Tiles are whole blocks, so a block never straddles two tiles.
    const int blockWidth = kBlockWidth * step, blockHeight = kBlockHeight * step;
    const int tileWidth = std::max(blockWidth, options.tileSize / blockWidth * blockWidth);
    const int tileHeight = std::max(blockHeight, options.tileSize / blockHeight * blockHeight);
    const int tilesX = (width + tileWidth - 1) / tileWidth, tilesY = (height + tileHeight - 1) / tileHeight;
    std::atomic<bool> stopped{false};
    // One tile's buffers per thread for the whole pass: the scheduler hands out many small
    // ranges, and each would otherwise allocate and clear a tile of samples.
    tbb::enumerable_thread_specific<TileAovs> tiles([&] { return TileAovs(targets, pass, step, tileWidth, tileHeight); });
    tbb::parallel_for(tbb::blocked_range<int>(0, tilesX * tilesY), [&](const tbb::blocked_range<int>& range) {
        Block block;
        block.step = step;
        block.offset = offset;
        TileAovs& tile = tiles.local();
        for (int t = range.begin(); t != range.end(); ++t) {
            if (stopped.load(std::memory_order_relaxed) || (stop && stop())) {
                stopped = true;
                return;
            }
            const int x0 = (t % tilesX) * tileWidth, y0 = (t / tilesX) * tileHeight;
            const int x1 = std::min(x0 + tileWidth, width), y1 = std::min(y0 + tileHeight, height);
            // A tile no primary ray can hit holds the background, which the centre pass looked up
            // filtered over the pixel's footprint already: later passes leave it.
            if (pass > 0 && !context.scene.overlaps(x0, y0, x1, y1)) continue;
            for (int by = y0; by < y1; by += blockHeight)
                for (int bx = x0; bx < x1; bx += blockWidth) {
                    block.count = 0;
                    for (int y = by; y < std::min(by + blockHeight, y1); y += step)
                        for (int x = bx; x < std::min(bx + blockWidth, x1); x += step) {
                            block.x[block.count] = x;
                            block.y[block.count] = y;
                            block.pixels[block.count++] = &tile.pixel(x - x0, y - y0);
                        }
                    shadeBlock(context, block);
                }
            tile.flush(x0, y0, x1, y1, blend);
        }
    });
#ifndef NDEBUG
    if (!stopped) requireFiniteRadiometric(targets);
#endif
    return !stopped;
}

}  // namespace

int passCount(const RenderOptions& options) { return options.samplesPerPixel >= 2 ? options.samplesPerPixel + 1 : 1; }

bool renderPass(const Frame& frame, const CameraView& camera, const RenderOptions& options, const AovTargets& targets,
                int pass, const std::function<bool()>& stop) {
    return renderSamples(frame, camera, options, targets, pass, 1, stop);
}

bool renderDraft(const Frame& frame, const CameraView& camera, const RenderOptions& options, const AovTargets& targets,
                 int block, const std::function<bool()>& stop) {
    if (block < 1) throw Error("renderer: draft block " + std::to_string(block) + " is not a positive size");
    return renderSamples(frame, camera, options, targets, 0, block, stop);
}

}  // namespace opal
