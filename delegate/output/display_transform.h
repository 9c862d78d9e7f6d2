// Working space -> display/view: turns a scene-linear frame into the display-referred
// values an artist sees (the preview writer quantizes them; the viewer uploads them).
#pragma once

#include "delegate/output/color_config.h"
#include "delegate/output/image.h"

#include <string>

namespace opal {

class DisplayTransform {
public:
    // Throws opal::Error listing the available displays or views when one is unknown.
    DisplayTransform(const ColorConfig& config, std::string display, std::string view);
    // The config's default display and its default view.
    explicit DisplayTransform(const ColorConfig& config);

    const std::string& display() const { return display_; }
    const std::string& view() const { return view_; }

    // RGB or RGBA input: the color channels go through OCIO, alpha is copied untouched.
    // Color is transformed as given (premultiplied renders stay premultiplied). Rows are
    // processed in parallel (TBB). Throws opal::Error for other channel counts.
    Image apply(const Image& sceneLinear) const;
    void applyInPlace(Image& image) const;

private:
    std::string display_;
    std::string view_;
    OCIO::ConstCPUProcessorRcPtr processor_;
};

}  // namespace opal
