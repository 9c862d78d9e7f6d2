#include "examples/opal-view/core/environment_edit.h"

#include "schema/error.h"

#include <cmath>
#include <numbers>

namespace opal::view {

std::optional<hd::SdfPath> environmentLight(const scene::Scene& scene) {
    for (const auto& [path, light] : scene.lights)
        if (light.desc.kind == hd::LightKind::Dome) return path;
    return std::nullopt;
}

void rotateEnvironment(hd::LightDesc& dome, double degrees) {
    Imath::M44d turn;
    turn.setAxisAngle(Imath::V3d(0.0, 1.0, 0.0), degrees * std::numbers::pi / 180.0);
    dome.transform = dome.transform * turn;  // row vectors: the dome's own rotation first
}

double environmentRotation(const hd::LightDesc& dome) {
    Imath::V3d x;
    dome.transform.multDirMatrix(Imath::V3d(1.0, 0.0, 0.0), x);
    // Turning +X by a about +Y gives (cos a, 0, -sin a).
    return std::atan2(-x.z, x.x) * 180.0 / std::numbers::pi;
}

void setEnvironmentTexture(hd::LightDesc& dome, const std::filesystem::path& file) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file, error))
        throw Error(file.string() + ": no such image for the environment");
    dome.textureFile = std::filesystem::absolute(file).lexically_normal().string();
}

}  // namespace opal::view
