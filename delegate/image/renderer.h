// Image formation (docs/ARCHITECTURE.md#image-formation; hdEmbree's renderer): Embree
// primary rays against the committed render meshes, tiled over TBB. Per sample that hits:
//   subsurface = F_t(eta, n.w_o) sum_j b_j L(v_j)      barycentric over the hit triangle's
//                                                      per-vertex radiance L (no F_t(w_o))
//   specular   = GGX of every analytic light (shadow rays) + the dome reflection (specular.h)
//   emission   = the shadow-field lights' emitters the ray passes in front of the hit (or
//                with no hit), seen through their baked views (shadow_field_light.h):
//                additive, as a flame is; depth and primId are then the emitter's
//   color      = subsurface + specular + emission, alpha 1
// and where nothing is hit, the visible domes + emission (or nothing: opal:transparentBackground).
// Pixels converge over passes of sub-pixel samples (renderPass below). The renderer reads
// only a committed Frame: prims may change while it runs.
#pragma once

#include "delegate/relight/analytic_light.h"
#include "delegate/image/camera_view.h"
#include "delegate/relight/environment_light.h"
#include "delegate/relight/shadow_field_light.h"
#include "delegate/hd/aov.h"
#include "delegate/hd/scene_delegate.h"
#include "delegate/hd/render_buffer.h"
#include "delegate/image/pixel_filter.h"
#include "raytrace/ray_scene.h"
#include "schema/asset/translucent_asset.h"

#include <Imath/ImathMatrix.h>

#include <array>
#include <functional>
#include <memory>
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
    double roughness = hd::kDefaultSpecularRoughness;
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
    // Shadow-field lights whose emitters the camera sees; emitter k has primId
    // meshes.size() + k.
    std::vector<std::shared_ptr<const ShadowFieldLight>> emitters;
};

struct RenderOptions {
    bool specular = true;
    bool transparentBackground = false;
    int tileSize = 32;
    int samplesPerPixel = 16;
    PixelFilter filter = PixelFilter::Box;
    int draftBlock = 1;  // > 1: a draft before pass 0 (renderDraft); 1: none
};

// The buffer each AOV goes to (hd::AovId order); null: not rendered. Each must be allocated
// to the camera's size with the AOV's channel count.
using AovTargets = std::array<hd::RenderBuffer*, hd::kAovCount>;

// Image formation is progressive: pass 0 traces the ray through each pixel's centre and
// writes every bound AOV (the nearest ones, depth, primId and normal, only then); with
// samplesPerPixel >= 2, passes 1..samplesPerPixel each trace sample p - 1 of the pixel's
// pattern (sample_pattern.h) and update the filtered AOVs to the filter-weighted mean of
// the samples so far (pixel_filter.h), which pass 1 starts afresh. So the image after pass
// 0 is the single-sample image, and the converged one holds samplesPerPixel samples.
// Tiles outside the scene's projected bounds see only the background, which pass 0 looks up
// filtered over each pixel's footprint (DomeLookup at the pixel's angle): later passes skip
// them.
int passCount(const RenderOptions& options);

// Renders pass `pass` tile by tile into the targets (each tile written whole, under the
// buffer's tile lock). Before each tile it asks `stop`: when that says true the pass ends
// there and renderPass returns false; true when every tile was rendered.
bool renderPass(const Frame& frame, const CameraView& camera, const RenderOptions& options, const AovTargets& targets,
                int pass, const std::function<bool()>& stop = {});

// The draft an interactive host shows first: pass 0 with one ray per `block` x `block` cell
// of pixels (through the cell's centre), its values written to every pixel of the cell
// (the last row and column of cells clipped to the image). It writes every bound AOV, as
// pass 0 does, which then overwrites every pixel: the passes after it are unchanged.
// Throws opal::Error for a block below 1; returns as renderPass.
bool renderDraft(const Frame& frame, const CameraView& camera, const RenderOptions& options, const AovTargets& targets,
                 int block, const std::function<bool()>& stop = {});

}  // namespace opal
