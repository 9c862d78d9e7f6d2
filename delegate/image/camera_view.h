// The primary rays of a camera (UsdGeomCamera) through an image of width x height pixels.
//
// Conventions (delegate/DELEGATE.md): the camera looks down its local -Z axis, +X is to
// the right of the image and +Y up; pixel (x, y) has its centre at (x + 0.5, y + 0.5) with
// row 0 at the top. The film (horizontal x vertical aperture at focalLength) is fitted
// into the image ("fit" conform, as usdview): the whole aperture is visible, pixels are
// square, and the image's extra width or height extends the view. The camera's transform
// may rotate, translate and scale uniformly (the scale is ignored); depth along the view
// axis is then in world units.
#pragma once

#include "delegate/hd/scene_delegate.h"
#include "raytrace/ray_scene.h"

#include <Imath/ImathMatrix.h>
#include <Imath/ImathVec.h>

namespace opal {

// Throws opal::Error naming `id` for a non-positive focal length or aperture, a clip range
// that is not 0 < near < far, or a transform that is not a rotation, uniform scale and
// translation.
void validateCamera(const hd::CameraDesc& desc, const hd::SdfPath& id);

class CameraView {
public:
    // Throws opal::Error naming `id` as OpalCamera::sync does, or for a non-positive size.
    CameraView(const hd::CameraDesc& desc, int width, int height, const hd::SdfPath& id);

    int width() const { return width_; }
    int height() const { return height_; }
    // The ray through image position (px, py) in pixels (x right, y down): its direction has
    // a camera-space z of -1, so the ray parameter t is the depth along the view axis.
    // t runs over [nearClip, farClip]. In float, from per-view constants: the pixel loop
    // asks for one per pixel.
    Ray ray(double px, double py) const {
        const Imath::V3f d = stepX_ * float(px) + stepY_ * float(py) + corner_;
        return {originF_, d, float(near_), float(far_)};
    }
    // Pixels whose rays may reach the world box: [x0, x1) x [y0, y1), conservative (one
    // pixel of margin; the whole image when part of the box is not in front of the camera;
    // empty for an empty box). Pixels outside it need no primary ray.
    struct PixelRect {
        int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
        bool overlaps(int ax0, int ay0, int ax1, int ay1) const { return ax0 < x1 && x0 < ax1 && ay0 < y1 && y0 < ay1; }
    };
    PixelRect pixelBounds(const Imath::Box3f& world) const;
    // The angle a pixel subtends at the image centre (radians).
    double pixelAngle() const { return 2.0 * halfHeight_ / height_; }
    const Imath::V3d& position() const { return origin_; }

private:
    int width_ = 0, height_ = 0;
    Imath::V3d origin_;
    Imath::M33d rotation_;  // camera to world, row vectors
    double halfWidth_ = 0.0, halfHeight_ = 0.0;  // the image's half extents on the plane z = -1
    double near_ = 0.0, far_ = 0.0;
    // World direction = stepX px + stepY py + corner (the ray through (px, py)).
    Imath::V3f originF_, stepX_, stepY_, corner_;
};

}  // namespace opal
