// The rendered picture on screen: a texture holding the newest display-referred image and
// a full-window triangle that draws it (image row 0 at the top of the window).
#pragma once

#include "delegate/output/image.h"

namespace opal::view {

class PictureTexture {
public:
    // Needs the current OpenGL 3.3 core context; throws opal::Error with the compiler's log
    // when a shader does not build.
    PictureTexture();
    ~PictureTexture();
    PictureTexture(const PictureTexture&) = delete;
    PictureTexture& operator=(const PictureTexture&) = delete;

    // `displayReferred`: RGB in [0, 1].
    void upload(const Image& displayReferred);
    bool empty() const { return width_ == 0; }
    // Fills the viewport with the picture (the clear colour before the first upload).
    void draw() const;

private:
    unsigned texture_ = 0, program_ = 0, vertexArray_ = 0;
    int width_ = 0, height_ = 0;
};

}  // namespace opal::view
