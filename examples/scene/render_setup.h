// What a batch render of a scene uses, decided as usdrecord decides it: the camera is the
// one asked for, else the RenderSettings prim's camera, else the scene's only camera; the
// resolution is the one asked for, else the RenderSettings prim's, else DefaultWidth
// pixels wide at the camera's aperture ratio (so the film fills the image).
#pragma once

#include "examples/scene/scene.h"

#include <optional>

namespace opal::scene {

struct RenderRequest {
    std::optional<hd::SdfPath> camera;      // --camera
    std::optional<Resolution> resolution;   // --resolution
};

struct RenderSetup {
    hd::SdfPath camera;
    Resolution resolution;
};

inline constexpr int DefaultWidth = 640;

// Throws opal::Error naming the scene file when the requested camera is not a Camera
// prim of the scene, when the scene has no camera, or when it has several and neither
// the request nor a RenderSettings prim picks one (each message lists the cameras).
RenderSetup chooseRenderSetup(const Scene& scene, const RenderRequest& request);

}  // namespace opal::scene
