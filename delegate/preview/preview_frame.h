// One preview frame: a ray through each pixel's centre (one sample, no anti-aliasing),
// the closest hit shaded (preview_shading.h), in parallel over rows with TBB. What every
// AOV the preview writes needs, per pixel.
#pragma once

#include "delegate/image/camera_view.h"
#include "delegate/preview/preview_scene.h"
#include "delegate/preview/preview_shading.h"

#include <limits>
#include <vector>

namespace opal::preview {

struct PreviewPixel {
    float color[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // premultiplied: A is 1 on a mesh, else 0
    float normal[3] = {0.0f, 0.0f, 0.0f};       // world, unit; 0 where nothing was hit
    float depth = std::numeric_limits<float>::infinity();  // along the view axis
    float primId = -1.0f;
};

struct FrameLook {
    Shading shading = Shading::Lambert;
    double headlight = 1.0;
};

// width x height pixels, row 0 at the top.
std::vector<PreviewPixel> renderFrame(const PreviewScene& scene, const CameraView& view, const FrameLook& look);

}  // namespace opal::preview
