#include "delegate/image/camera_view.h"

#include "delegate/relight/irradiance.h"
#include "schema/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace opal {

void validateCamera(const hd::CameraDesc& d, const hd::SdfPath& id) {
    const auto fail = [&](const std::string& what) { throw Error("camera '" + id + "': " + what); };
    if (!(d.focalLength > 0.0) || !std::isfinite(d.focalLength))
        fail("focal length " + std::to_string(d.focalLength) + " is not positive");
    if (!(d.horizontalAperture > 0.0) || !(d.verticalAperture > 0.0) || !std::isfinite(d.horizontalAperture) ||
        !std::isfinite(d.verticalAperture))
        fail("apertures " + std::to_string(d.horizontalAperture) + " x " + std::to_string(d.verticalAperture) +
             " are not positive");
    if (!(d.nearClip > 0.0) || !(d.farClip > d.nearClip))
        fail("clipping range [" + std::to_string(d.nearClip) + ", " + std::to_string(d.farClip) +
             "] is not 0 < near < far");
    try {
        rotationOf(d.transform, "transform");
    } catch (const Error& e) {
        fail(e.what());
    }
}

CameraView::CameraView(const hd::CameraDesc& desc, int width, int height, const hd::SdfPath& id)
    : width_(width), height_(height), near_(desc.nearClip), far_(desc.farClip) {
    validateCamera(desc, id);
    if (width <= 0 || height <= 0)
        throw Error("camera '" + id + "': image size " + std::to_string(width) + " x " + std::to_string(height) +
                    " is not positive");
    rotation_ = rotationOf(desc.transform, "camera");
    desc.transform.multVecMatrix(Imath::V3d(0.0), origin_);
    // Fit: the aperture inside the image, the other dimension extended.
    halfWidth_ = 0.5 * desc.horizontalAperture / desc.focalLength;
    halfHeight_ = 0.5 * desc.verticalAperture / desc.focalLength;
    const double imageAspect = double(width) / double(height);
    if (imageAspect > halfWidth_ / halfHeight_)
        halfWidth_ = halfHeight_ * imageAspect;
    else
        halfHeight_ = halfWidth_ / imageAspect;
    // Camera-space direction (sx, sy, -1), sx = (2 px / width - 1) halfWidth,
    // sy = (1 - 2 py / height) halfHeight, turned into the world by the rotation's rows.
    const Imath::V3d right(rotation_[0][0], rotation_[0][1], rotation_[0][2]);
    const Imath::V3d up(rotation_[1][0], rotation_[1][1], rotation_[1][2]);
    const Imath::V3d back(rotation_[2][0], rotation_[2][1], rotation_[2][2]);
    originF_ = Imath::V3f(origin_);
    stepX_ = Imath::V3f(right * (2.0 * halfWidth_ / width_));
    stepY_ = Imath::V3f(up * (-2.0 * halfHeight_ / height_));
    corner_ = Imath::V3f(right * -halfWidth_ + up * halfHeight_ - back);
}


// Each corner into camera space (row vectors: world = camera * rotation_, so camera =
// world * rotation_^T), then onto the image by inverting ray(): px = (sx / halfWidth + 1)
// width / 2 and py = (1 - sy / halfHeight) height / 2 with (sx, sy) = (x, y) / -z.
CameraView::PixelRect CameraView::pixelBounds(const Imath::Box3f& world) const {
    if (world.isEmpty()) return {};
    const PixelRect whole{0, 0, width_, height_};
    const Imath::M33d toCamera = rotation_.transposed();
    double xMin = 1e300, yMin = 1e300, xMax = -1e300, yMax = -1e300;
    for (int corner = 0; corner < 8; ++corner) {
        const Imath::V3d p((corner & 1) ? world.max.x : world.min.x, (corner & 2) ? world.max.y : world.min.y,
                           (corner & 4) ? world.max.z : world.min.z);
        const Imath::V3d c = (p - origin_) * toCamera;
        if (!(c.z < -1e-9 * std::max(1.0, c.length()))) return whole;  // at or behind the camera plane
        const double px = (c.x / -c.z / halfWidth_ + 1.0) * 0.5 * width_;
        const double py = (1.0 - c.y / -c.z / halfHeight_) * 0.5 * height_;
        xMin = std::min(xMin, px), xMax = std::max(xMax, px), yMin = std::min(yMin, py), yMax = std::max(yMax, py);
    }
    const auto clampTo = [](double v, int hi) { return int(std::clamp(v, 0.0, double(hi))); };
    return {clampTo(std::floor(xMin) - 1.0, width_), clampTo(std::floor(yMin) - 1.0, height_),
            clampTo(std::ceil(xMax) + 1.0, width_), clampTo(std::ceil(yMax) + 1.0, height_)};
}

}  // namespace opal
