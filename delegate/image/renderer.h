// Image formation (DESIGN.md s.7; hdEmbree's renderer): Embree primary rays against the
// committed render meshes, tiled over TBB. Per hit:
//   subsurface = F_t(eta, n.w_o) sum_j b_j L(v_j)      barycentric over the hit triangle's
//                                                      per-vertex radiance L (no F_t(w_o))
//   specular   = GGX of every analytic light (shadow rays) + the dome reflection (specular.h)
//   color      = subsurface + specular, alpha 1
// and where nothing is hit, the visible domes (or nothing: opal:transparentBackground).
// The renderer reads only a committed Frame: prims may change while it runs.
#pragma once

#include "delegate/relight/analytic_light.h"
#include "delegate/image/camera_view.h"
#include "delegate/relight/environment_light.h"
#include "delegate/hd/types.h"
#include "raytrace/ray_scene.h"
#include "schema/asset/translucent_asset.h"

#include <Imath/ImathMatrix.h>

#include <memory>
#include <span>
#include <vector>

namespace opal {

// One mesh as the renderer shades it: the relit per-vertex values of the last commit.
struct MeshShading {
    std::shared_ptr<const TranslucentAsset> asset;  // render-mesh topology and normals
    Imath::M33f normalToWorld;                      // rotation of the mesh's transform
    std::shared_ptr<const std::vector<float>> vertexRadiance;  // L(x_o) per render-mesh vertex, RGB
    // E per render-mesh vertex, RGB: shared by successive commits while the lights and eta
    // stay (a sigma edit does not change it).
    std::shared_ptr<const std::vector<float>> vertexIrradiance;
    double eta = 1.3;
    bool specular = true;
    double roughness = 0.35;
    int primId = -1;
};

struct DomeView {
    std::shared_ptr<const LatLongMap> map;
    Imath::M33d domeFromWorld;
    Rgb scale{1.0, 1.0, 1.0};  // color * intensity * 2^exposure
    bool visibleToCamera = true;
};

// The committed scene: immutable once built (the delegate publishes a new one per commit).
struct Frame {
    std::shared_ptr<const RayScene> rays;                 // every visible mesh
    std::vector<std::shared_ptr<const MeshShading>> meshes;  // by ray-scene prim number
    std::vector<AnalyticLight> lights;
    std::vector<DomeView> domes;
};

struct RenderOptions {
    bool specular = true;
    bool transparentBackground = false;
    int tileSize = 32;
};

// Where each AOV goes (row-major, row 0 at the top, width x height x channels); null
// targets are skipped. Channel counts: aovChannelCount.
struct AovTargets {
    float* color = nullptr;       // R G B A
    float* subsurface = nullptr;  // R G B
    float* specular = nullptr;    // R G B
    float* irradiance = nullptr;  // R G B
    float* normal = nullptr;      // X Y Z
    float* depth = nullptr;       // Z
    float* primId = nullptr;      // id
    float* alpha = nullptr;       // A
};

// The AOVs Opal fills (hd::Aov), and the channels of each; 0 for an unknown name.
std::span<const hd::Token> supportedAovs();
int aovChannelCount(const hd::Token& aov);

void renderFrame(const Frame& frame, const CameraView& camera, const RenderOptions& options, const AovTargets& targets);

}  // namespace opal
