// The scene's environment as the Environment panel and scripts edit it: the first dome
// light in path order, its lat-long texture, its turn about the world's up axis (+Y) and
// whether the camera sees it behind the asset. The background switch is the delegate's
// (hd::LightDesc::visibleToCamera); UsdLux has no attribute for it, so a saved scene
// keeps it as Opal's own `opal:visibleToCamera`, which the scene reader reads.
#pragma once

#include "examples/scene/scene.h"

#include <filesystem>
#include <optional>

namespace opal::view {

std::optional<hd::SdfPath> environmentLight(const scene::Scene& scene);

// The dome turned by `degrees` about the world's +Y (counter-clockwise seen from above),
// after whatever rotation it has (a Z-up scene's orientation stays).
void rotateEnvironment(hd::LightDesc& dome, double degrees);

// The dome's turn about +Y in degrees, in (-180, 180]: the angle of its +X axis seen from above.
double environmentRotation(const hd::LightDesc& dome);

// A lat-long image for the dome. Throws opal::Error naming the file when it does not exist.
void setEnvironmentTexture(hd::LightDesc& dome, const std::filesystem::path& file);

}  // namespace opal::view
