// What the render tests share: a small lossless translucent sphere made in the test (no bake
// library), a scene source that counts what prims pull, and a way to render AOVs through
// the abstract API only (as a host that loaded the delegate from a plugin).
#pragma once

#include "delegate/hd/render_index.h"
#include "delegate/hd/render_to_convergence.h"
#include "schema/error.h"
#include "tests/relight/synthetic_asset.h"
#include "tests/relight/translation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace opal::test {

// Completes an asset whose samples and render mesh are placed: a basis fitted over a narrow
// range around `material` with every pair of samples inside rMax, the lossless transfer,
// (with envFaceSize > 0) environment vectors with 3 Fresnel terms, and per-vertex weights
// onto the 4 nearest samples (inverse distance).
inline void finishAsset(TranslucentAsset& asset, const Material& material, double rMax, std::uint32_t envFaceSize) {
    asset.unitsPerMm = 1.0;
    asset.defaultMaterial = material;
    asset.range = rangeAround(material, 1.5, 1.3, 1.5);
    ProfileBasisSettings settings;
    settings.K = 12;
    settings.rMax = rMax;
    settings.radialSamples = 512;
    settings.trainingMaterials = 256;
    settings.range = asset.range;
    asset.basis = ProfileBasis::fit(settings);
    buildTransfer(asset, 1.0, 1.0);
    if (envFaceSize > 0)
        asset.environment = environmentTransfer(asset, envFaceSize, 3, [](std::size_t, const Imath::V3f&) { return true; });

    VertexWeights& w = asset.vertexWeights;
    w.offsets = {0};
    for (const Imath::V3f& p : asset.mesh.points) {
        std::vector<std::pair<float, std::uint32_t>> nearest;
        for (std::uint32_t i = 0; i < asset.samples.size(); ++i)
            nearest.emplace_back((asset.samples[i].position - p).length(), i);
        std::partial_sort(nearest.begin(), nearest.begin() + 4, nearest.end());
        float sum = 0.0f;
        for (int j = 0; j < 4; ++j) sum += 1.0f / std::max(nearest[j].first, 1e-6f);
        for (int j = 0; j < 4; ++j) {
            w.samples.push_back(nearest[j].second);
            w.weights.push_back(1.0f / std::max(nearest[j].first, 1e-6f) / sum);
        }
        w.offsets.push_back(std::uint32_t(w.samples.size()));
    }
}

inline const Material& testMaterial() {
    static const Material material{{1.2, 0.9, 0.7}, {0.05, 0.1, 0.2}, 1.4};
    return material;
}

// The cube-sphere of synthetic_asset.h (6 x 2^log2Size^2 samples, radius in mm).
inline std::shared_ptr<TranslucentAsset> sphereAsset(std::uint32_t log2Size = 3, float radius = 5.0f,
                                                     std::uint32_t envFaceSize = 4,
                                                     Material material = testMaterial()) {
    auto asset = std::make_shared<TranslucentAsset>();
    asset->name = "testSphere";
    makeCubeSphere(*asset, log2Size, radius);
    finishAsset(*asset, material, 2.2 * radius, envFaceSize);
    return asset;
}

// A flat square, side mm on the plane y = 0 from (0, 0, 0) to (side, 0, side), normal +Y:
// makeSlab's 8 x 8 samples and one quad as its render mesh. Its edges are straight lines.
inline std::shared_ptr<TranslucentAsset> squareAsset(float side = 8.0f) {
    auto asset = std::make_shared<TranslucentAsset>();
    asset->name = "testSquare";
    makeSlab(*asset, 1, 1, 3, side / 8.0f);
    asset->mesh.points = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, side}, {side, 0.0f, side}, {side, 0.0f, 0.0f}};
    asset->mesh.normals.assign(4, Imath::V3f(0.0f, 1.0f, 0.0f));
    asset->mesh.faceVertexCounts = {4};
    asset->mesh.faceVertexIndices = {0, 1, 2, 3};
    finishAsset(*asset, testMaterial(), 1.5 * side, 0);
    return asset;
}

// One asset shared by the tests of a process (the transfer takes a moment to build).
inline std::shared_ptr<const TranslucentAsset> sharedSphere() {
    static const std::shared_ptr<const TranslucentAsset> sphere = sphereAsset();
    return sphere;
}


inline hd::LightDesc pointLight(const Imath::V3d& at, double intensity, Rgb color = {1.0, 1.0, 1.0}) {
    hd::LightDesc d;
    d.kind = hd::LightKind::Sphere;
    d.treatAsPoint = true;
    d.intensity = intensity;
    d.color = color;
    d.transform = translation(at.x, at.y, at.z);
    return d;
}

// A scene source answering from maps, counting every pull per prim.
class CountingScene : public hd::SceneDelegate {
public:
    std::map<hd::SdfPath, hd::MeshDesc> meshes;
    std::map<hd::SdfPath, hd::MaterialDesc> materials;
    std::map<hd::SdfPath, hd::LightDesc> lights;
    std::map<hd::SdfPath, hd::CameraDesc> cameras;
    mutable std::map<hd::SdfPath, int> pulls;

    hd::MeshDesc mesh(const hd::SdfPath& id) const override { return find(meshes, id); }
    hd::MaterialDesc material(const hd::SdfPath& id) const override { return find(materials, id); }
    hd::LightDesc light(const hd::SdfPath& id) const override { return find(lights, id); }
    hd::CameraDesc camera(const hd::SdfPath& id) const override { return find(cameras, id); }

    int pullCount(const hd::SdfPath& id) const {
        const auto it = pulls.find(id);
        return it == pulls.end() ? 0 : it->second;
    }
    int totalPulls() const {
        int n = 0;
        for (const auto& [id, count] : pulls) n += count;
        return n;
    }

private:
    template <typename T>
    T find(const std::map<hd::SdfPath, T>& map, const hd::SdfPath& id) const {
        ++pulls[id];
        const auto it = map.find(id);
        if (it == map.end()) throw Error("counting scene: no prim '" + id + "'");
        return it->second;
    }
};

// A camera at (0, 0, distance) looking down -Z, 36 x 24 film, 50 mm lens.
inline hd::CameraDesc frontCamera(double distance = 30.0) {
    hd::CameraDesc c;
    c.transform = translation(0.0, 0.0, distance);
    return c;
}

// Every AOV of one render, as plain arrays.
struct Aovs {
    int width = 0, height = 0;
    std::map<hd::Token, std::vector<float>> data;
    std::map<hd::Token, int> channels;

    const float* at(const hd::Token& aov, int x, int y) const {
        return data.at(aov).data() + (std::size_t(y) * width + x) * std::size_t(channels.at(aov));
    }
};

inline std::vector<hd::Token> allAovs() {
    std::vector<hd::Token> aovs;
    for (const hd::AovDescriptor& aov : hd::aovTable()) aovs.push_back(aov.name);
    return aovs;
}

// Anti-aliasing blends a pixel with what its neighbours show only along silhouettes: a pixel
// whose 3 x 3 neighbourhood's centre rays all hit (interior) or all miss (background) holds
// one surface or the background alone. Image borders count as neither.
inline bool neighbourhoodIs(const Aovs& a, int x, int y, bool hit) {
    if (x < 1 || y < 1 || x + 1 >= a.width || y + 1 >= a.height) return false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            if ((a.at("primId", x + dx, y + dy)[0] >= 0.0f) != hit) return false;
    return true;
}
inline bool interior(const Aovs& a, int x, int y) { return neighbourhoodIs(a, x, y, true); }
inline bool background(const Aovs& a, int x, int y) { return neighbourhoodIs(a, x, y, false); }

// Renders every AOV through the abstract API (the delegate may come from a plugin).
inline Aovs renderAovs(hd::RenderDelegate& delegate, hd::RenderIndex& index, const hd::SdfPath& camera, int width,
                       int height) {
    std::vector<std::unique_ptr<hd::RenderBuffer>> buffers;
    std::vector<hd::AovBinding> bindings;
    for (const hd::Token& aov : allAovs()) {
        buffers.push_back(std::make_unique<hd::RenderBuffer>("/Buffers/" + aov));
        bindings.push_back({aov, buffers.back().get()});
    }
    std::unique_ptr<hd::RenderPass> pass = delegate.createRenderPass(index);
    hd::RenderPassState state;
    state.camera = camera;
    state.width = width;
    state.height = height;
    hd::renderToConvergence(delegate, *pass, state, bindings);
    Aovs out;
    out.width = width;
    out.height = height;
    for (std::size_t i = 0; i < bindings.size(); ++i) {
        const hd::RenderBuffer& b = *buffers[i];
        out.data[bindings[i].aov].assign(b.data().begin(), b.data().end());
        out.channels[bindings[i].aov] = b.channels();
    }
    return out;
}

// The standard test scene: the sphere at the origin, a camera in front, named prims.
inline const hd::SdfPath SpherePath = "/World/Sphere";
inline const hd::SdfPath CameraPath = "/World/Camera";

inline void addSphere(CountingScene& scene, hd::RenderIndex& index, const hd::SdfPath& path = SpherePath,
                      const Imath::M44d& transform = Imath::M44d(), const hd::SdfPath& material = {}) {
    scene.meshes[path] = hd::MeshDesc{sharedSphere(), transform, material, true};
    index.insertRprim(hd::PrimType::TranslucentMesh, scene, path);
}

inline void addCamera(CountingScene& scene, hd::RenderIndex& index, const hd::CameraDesc& camera = frontCamera()) {
    scene.cameras[CameraPath] = camera;
    index.insertSprim(hd::PrimType::Camera, scene, CameraPath);
}

inline void addLight(CountingScene& scene, hd::RenderIndex& index, const hd::SdfPath& path, const hd::LightDesc& desc) {
    scene.lights[path] = desc;
    const hd::Token type = desc.kind == hd::LightKind::Dome          ? hd::PrimType::DomeLight
                           : desc.kind == hd::LightKind::Distant     ? hd::PrimType::DistantLight
                           : desc.kind == hd::LightKind::ShadowField ? hd::PrimType::ShadowFieldLight
                                                                     : hd::PrimType::SphereLight;
    index.insertSprim(type, scene, path);
}

// Sum of the RGB of an AOV over pixels [x0, x1) x [y0, y1).
inline double sumRgb(const Aovs& aovs, const hd::Token& aov, int x0, int x1, int y0, int y1) {
    double sum = 0.0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            for (int c = 0; c < 3; ++c) sum += aovs.at(aov, x, y)[c];
    return sum;
}

// max |a - b| / max |b| over two AOV arrays.
inline double maxRelativeDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double diff = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if (!std::isfinite(a[i]) && !std::isfinite(b[i]) && a[i] == b[i]) continue;
        diff = std::max(diff, std::abs(double(a[i]) - double(b[i])));
        scale = std::max(scale, std::abs(double(b[i])));
    }
    return scale > 0.0 ? diff / scale : diff;
}

}  // namespace opal::test
