// The camera Sprim (UsdGeomCamera): it pulls its hd::CameraDesc; render passes turn it into
// primary rays (image/camera_view.h, which states the conventions).
#pragma once

#include "delegate/hd/prim.h"

namespace opal {

class OpalCamera final : public hd::Sprim {
public:
    using hd::Sprim::Sprim;

    // Pulls the description on any dirty bit; throws opal::Error naming the prim for a
    // non-positive focal length or aperture, a clip range that is not 0 < near < far, or a
    // transform that is not a rotation, uniform scale and translation.
    void sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) override;
    hd::DirtyBits initialDirtyBits() const override { return hd::Dirty::Transform | hd::Dirty::Params; }

    const hd::CameraDesc& desc() const { return desc_; }

private:
    hd::CameraDesc desc_;
};

}  // namespace opal
