// What the render thread renders: the committed frame through one camera into the bound
// buffers, with the delegate's image settings. Two jobs that are the same picture (sameAs)
// need no restart: a host calling execute again with nothing changed lets the frame go on.
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "delegate/image/renderer.h"

#include <memory>

namespace opal {

struct RenderJob {
    std::shared_ptr<const Frame> frame;
    hd::CameraDesc camera;
    hd::SdfPath cameraPath;
    int width = 0, height = 0;
    AovTargets targets{};
    RenderOptions options;

    bool sameAs(const RenderJob& o) const {
        const hd::CameraDesc& a = camera;
        const hd::CameraDesc& b = o.camera;
        const bool sameCamera = a.transform == b.transform && a.focalLength == b.focalLength &&
                                a.horizontalAperture == b.horizontalAperture &&
                                a.verticalAperture == b.verticalAperture && a.nearClip == b.nearClip &&
                                a.farClip == b.farClip;
        // draftBlock is left out: the picture a job converges to does not depend on it.
        const RenderOptions& p = options;
        const RenderOptions& q = o.options;
        const bool sameOptions = p.specular == q.specular && p.transparentBackground == q.transparentBackground &&
                                 p.tileSize == q.tileSize && p.samplesPerPixel == q.samplesPerPixel &&
                                 p.filter == q.filter;
        return frame == o.frame && sameCamera && cameraPath == o.cameraPath && width == o.width &&
               height == o.height && targets == o.targets && sameOptions;
    }
};

}  // namespace opal
