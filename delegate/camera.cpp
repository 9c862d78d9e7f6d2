#include "delegate/camera.h"

#include "delegate/image/camera_view.h"

namespace opal {

void OpalCamera::sync(const hd::SceneDelegate& scene, hd::DirtyBits* dirtyBits) {
    if (*dirtyBits != hd::Dirty::Clean) {
        hd::CameraDesc desc = scene.camera(id());
        validateCamera(desc, id());
        desc_ = desc;
    }
    *dirtyBits = hd::Dirty::Clean;
}

}  // namespace opal
