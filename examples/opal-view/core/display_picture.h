// What the viewer shows of an AOV buffer: display-referred RGB in [0, 1]. Radiometric AOVs
// (filtered, three or four channels: color, subsurface, specular, irradiance, ...) are
// scaled by 2^exposure and go through the OCIO display/view transform, as opal-render's
// preview does; normals are remapped from [-1, 1], depth from its finite range (near is
// bright), ids and alpha to grey levels.
#pragma once

#include "delegate/hd/render_buffer.h"
#include "delegate/output/color_config.h"
#include "delegate/output/display_transform.h"
#include "delegate/output/image.h"

#include <string>

namespace opal::view {

// Whether an AOV is radiometric (filtered, RGB or RGBA): shown through the view transform.
bool isRadiometric(const std::string& aov);

// The buffer's pixels, copied while it is mapped (never half a tile). Empty before the
// render pass allocated it.
Image mappedImage(const hd::RenderBuffer& buffer);

// The adjustments around the view transform, for radiometric AOVs: exposure (stops) scales
// the scene-linear radiance before it; gamma raises the display-referred result to the
// power 1 / gamma after it, as a compositing viewer's gamma does.
struct DisplayGrade {
    double exposure = 0.0;
    double gamma = 1.0;  // > 0
    friend bool operator==(const DisplayGrade&, const DisplayGrade&) = default;
};

class DisplayPicture {
public:
    // The config's default display and view; throws opal::Error as DisplayTransform.
    explicit DisplayPicture(const ColorConfig& config);

    // Throws opal::Error listing the displays or views when one is unknown.
    void setDisplayView(const std::string& display, const std::string& view);
    const std::string& display() const { return transform_.display(); }
    const std::string& view() const { return transform_.view(); }
    const ColorConfig& config() const { return config_; }

    // `aov` names what `sceneLinear` holds (hd/aov.h). Returns an RGB image.
    Image toDisplay(const Image& sceneLinear, const std::string& aov, const DisplayGrade& grade) const;
    // What a saved PNG holds: toDisplay's picture, except that the color AOV keeps its
    // alpha (RGBA through the view, as opal-render's --preview), so it composites.
    Image toFile(const Image& sceneLinear, const std::string& aov, const DisplayGrade& grade) const;

private:
    ColorConfig config_;
    DisplayTransform transform_;
};

}  // namespace opal::view
