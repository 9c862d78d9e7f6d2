// Renders an emitter's views (schema/asset/emitter_views.h): for each of the 6 D^2 view
// directions, an orthographic P x P image of its bounding disk, each pixel the mean of
// 4 x 4 rays on a regular grid over its square (no jitter: the same bytes on every run),
// traced against the emitter along -v from outside its bounding sphere. Values are rounded
// as the sidecar stores them (binary16). Parallel over views.
#pragma once

#include "bake/light/emitter_scene.h"
#include "schema/asset/emitter_views.h"

#include <cstdint>

namespace opal {

EmitterViews renderEmitterViews(const EmitterScene& scene, std::uint32_t viewFaceSize, std::uint32_t imageSize);

}  // namespace opal
