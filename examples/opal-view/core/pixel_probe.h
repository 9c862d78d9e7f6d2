// The pixel probe: what every AOV holds at one pixel, scene-linear as the renderer wrote
// it (before the EXR's half floats), and what the picture on screen shows there; and which
// prim a pixel shows, from the primId AOV (the meshes by path, then the shadow-field lights,
// as the delegate numbers them).
#pragma once

#include "delegate/output/image.h"
#include "examples/opal-render/aov_buffers.h"
#include "examples/scene/scene.h"

#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace opal::view {

struct ProbedAov {
    std::string aov;
    std::vector<std::string> channels;  // "R", "G", ... as the EXR names them
    std::vector<float> values;
};

struct PixelProbe {
    int x = 0, y = 0;                  // from the top left
    std::vector<ProbedAov> aovs;       // every bound AOV, in binding order
    std::string shownAov;
    std::optional<std::array<float, 3>> display;  // the shown picture's RGB there, if shown
};

// Throws opal::Error when (x, y) lies outside the buffers (or they are not allocated yet).
std::vector<ProbedAov> probeAovs(const render::AovBuffers& buffers, int x, int y);

// "probe X Y" and one line per AOV, "  color R G B A = 0.1 0.2 0.3 1" (9 significant
// digits), then "  display (color) R G B = ..." when the picture is shown.
std::string probeReport(const PixelProbe& probe);

// The RGB at renderer pixel (x, y) of `shown`, a picture of a `width` x `height` render
// at any resolution (half while it is still changing); nothing outside it or when empty.
std::optional<std::array<float, 3>> shownValue(const Image& shown, int x, int y, int width, int height);

// The prim a primId value names in `scene` with its `disabled` lights left out (as the
// delegate numbers what it renders), if any.
std::optional<hd::SdfPath> primOfId(const scene::Scene& scene, const std::set<hd::SdfPath>& disabled, float id);

}  // namespace opal::view
