#include "examples/scene/render_setup.h"

#include "schema/error.h"

#include <algorithm>
#include <cmath>

namespace opal::scene {
namespace {

std::string cameraList(const Scene& scene) {
    std::string list;
    for (const auto& [path, camera] : scene.cameras) list += (list.empty() ? "<" : ", <") + path + ">";
    return list.empty() ? "none" : list;
}

hd::SdfPath chooseCamera(const Scene& scene, const RenderRequest& request) {
    const std::string file = scene.file.string();
    if (request.camera) {
        if (!scene.cameras.count(*request.camera))
            throw Error(file + ": --camera <" + *request.camera + "> is not a Camera prim of the scene (cameras: " +
                        cameraList(scene) + ")");
        return *request.camera;
    }
    if (scene.renderSettings && scene.renderSettings->camera) return *scene.renderSettings->camera;
    if (scene.cameras.empty()) throw Error(file + ": the scene has no Camera prim to render through");
    if (scene.cameras.size() > 1)
        throw Error(file + ": the scene has several cameras (" + cameraList(scene) +
                    "): choose one with --camera or a RenderSettings prim's rel camera");
    return scene.cameras.begin()->first;
}

Resolution defaultResolution(const hd::CameraDesc& camera) {
    const double height = DefaultWidth * camera.verticalAperture / camera.horizontalAperture;
    return {DefaultWidth, std::clamp(int(std::lround(height)), 1, Resolution::Max)};
}

}  // namespace

RenderSetup chooseRenderSetup(const Scene& scene, const RenderRequest& request) {
    RenderSetup setup;
    setup.camera = chooseCamera(scene, request);
    if (request.resolution) {
        setup.resolution = *request.resolution;
    } else if (scene.renderSettings && scene.renderSettings->resolution) {
        setup.resolution = *scene.renderSettings->resolution;
    } else {
        setup.resolution = defaultResolution(scene.cameras.at(setup.camera).desc);
    }
    return setup;
}

}  // namespace opal::scene
