// The OCIO display/view transform on the GPU, as usdview's colour-correction task and OCIO's
// ociodisplay do it: OCIO 2's GPU processor writes a GLSL function and the LUTs it samples
// (for Opal's ACES view, the exact ops, not a baked 3D LUT); this program splices the
// function into a fragment shader that applies the display grade around it, as
// DisplayPicture::toDisplay does on the CPU (exposure before, 1 / gamma after).
#pragma once

#include "delegate/output/color_config.h"
#include "examples/opal-view/core/display_picture.h"

#include <string>
#include <vector>

namespace opal::view {

class OcioDisplayProgram {
public:
    // Needs a current OpenGL 3.3 core context. Throws opal::Error for a display or view
    // the config lacks (listing them), a shader that does not build, or a uniform of a type
    // it cannot set.
    OcioDisplayProgram(const ColorConfig& config, const std::string& display, const std::string& view);
    ~OcioDisplayProgram();
    OcioDisplayProgram(const OcioDisplayProgram&) = delete;
    OcioDisplayProgram& operator=(const OcioDisplayProgram&) = delete;

    const std::string& display() const { return display_; }
    const std::string& view() const { return view_; }

    // Draws the viewport-filling triangle: each fragment is the scene-linear texel of the
    // texture bound to unit 0 at the same place, through the grade and the transform (the
    // texture's row 0 goes to the viewport's row 0). Binds the LUTs to units 1 and up.
    void draw(const DisplayGrade& grade, unsigned vertexArray) const;

private:
    struct Lut {
        unsigned texture = 0, target = 0;
        std::string sampler;
    };
    void uploadLuts(const OCIO::GpuShaderDescRcPtr& shader);
    void setUniforms() const;

    std::string display_, view_;
    OCIO::GpuShaderDescRcPtr shader_;  // its uniforms' getters read the processor's dynamic properties
    unsigned program_ = 0;
    std::vector<Lut> luts_;
};

}  // namespace opal::view
