// The rendered picture on screen: a texture holding the newest picture and a full-window
// triangle that draws it (image row 0 at the top of the window). A scene-linear picture is
// turned display-referred on the GPU (OcioDisplayProgram) into a texture of its own, once
// per upload or display change, so that redrawing the interface costs no transform and
// the CPU never runs the OCIO view for the window (files written keep the CPU path).
#pragma once

#include "delegate/output/color_config.h"
#include "delegate/output/image.h"
#include "examples/opal-view/core/display_picture.h"
#include "examples/opal-view/gl/ocio_display_program.h"

#include <memory>

namespace opal::view {

class PictureTexture {
public:
    // Needs the current OpenGL 3.3 core context; throws opal::Error with the compiler's log
    // when a shader does not build.
    PictureTexture();
    ~PictureTexture();
    PictureTexture(const PictureTexture&) = delete;
    PictureTexture& operator=(const PictureTexture&) = delete;

    // `displayReferred`: RGB in [0, 1], shown as it is (the AOVs that are not radiometric).
    void upload(const Image& displayReferred);
    // Scene-linear RGB or RGBA pixels (channels 3 or 4, row 0 at the top), shown through
    // the display set by setDisplay. Throws opal::Error for other channel counts or before
    // setDisplay.
    void uploadSceneLinear(const float* pixels, int width, int height, int channels);
    // The display and view scene-linear pictures go through, and the grade around it;
    // rebuilds the program when the config, display or view changed. Throws as
    // OcioDisplayProgram (the previous one stays then).
    void setDisplay(const ColorConfig& config, const std::string& display, const std::string& view,
                    const DisplayGrade& grade);

    bool empty() const { return width_ == 0; }
    // Fills the viewport with the picture (the clear colour before the first upload).
    void draw();
    // The display-referred picture drawn (RGB, before the window's 8-bit rounding): what a
    // pixel probe reports. Empty before the first upload.
    Image displayed();

private:
    void allocate(unsigned texture, int internalFormat, int width, int height);
    void transform();  // the scene-linear picture through the display program into displayed_

    unsigned source_ = 0, displayed_ = 0, framebuffer_ = 0, program_ = 0, vertexArray_ = 0;
    int width_ = 0, height_ = 0, sourceChannels_ = 0;
    bool sceneLinear_ = false, stale_ = false;  // stale_: displayed_ lags the source or the display
    std::unique_ptr<OcioDisplayProgram> display_;
    std::filesystem::path configFile_;
    DisplayGrade grade_;
};

}  // namespace opal::view
