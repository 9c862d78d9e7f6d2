#include "examples/opal-view/gl/picture_texture.h"

#include "examples/opal-view/gl/shader_program.h"
#include "schema/error.h"

#include <glad/gl.h>

#include <array>
#include <string>

namespace opal::view {
namespace {

constexpr const char* FragmentShader = R"(#version 330 core
in vec2 uv;
out vec4 colour;
uniform sampler2D picture;
void main() { colour = vec4(texture(picture, uv).rgb, 1.0); }
)";

void setFiltering(unsigned texture, int minify) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, minify);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

}  // namespace

PictureTexture::PictureTexture() {
    program_ = linkProgram(viewportTriangleShader(true), FragmentShader, "the picture");
    glGenVertexArrays(1, &vertexArray_);  // the core profile draws only with one bound
    glGenTextures(1, &source_);
    glGenTextures(1, &displayed_);
    glGenFramebuffers(1, &framebuffer_);
    setFiltering(source_, GL_NEAREST);  // the transform reads texel for texel
    setFiltering(displayed_, GL_LINEAR);
}

PictureTexture::~PictureTexture() {
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteTextures(1, &displayed_);
    glDeleteTextures(1, &source_);
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteProgram(program_);
}

void PictureTexture::allocate(unsigned texture, int internalFormat, int width, int height) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
}

void PictureTexture::upload(const Image& displayReferred) {
    if (displayReferred.empty() || displayReferred.channels() != 3) return;
    const int w = displayReferred.width(), h = displayReferred.height();
    if (w != width_ || h != height_) allocate(displayed_, GL_RGBA32F, w, h);
    glBindTexture(GL_TEXTURE_2D, displayed_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, w, h, GL_RGB, GL_FLOAT, displayReferred.pixels().data());
    width_ = w;
    height_ = h;
    sourceChannels_ = 0;  // the source texture is reallocated by the next scene-linear upload
    sceneLinear_ = stale_ = false;
}

void PictureTexture::uploadSceneLinear(const float* pixels, int width, int height, int channels) {
    if (channels != 3 && channels != 4)
        throw Error("the picture: a scene-linear upload needs RGB or RGBA, not " + std::to_string(channels) + " channels");
    if (!display_) throw Error("the picture: no display transform set before a scene-linear upload");
    if (width <= 0 || height <= 0) return;
    if (width != width_ || height != height_) allocate(displayed_, GL_RGBA32F, width, height);
    if (width != width_ || height != height_ || channels != sourceChannels_)
        allocate(source_, channels == 4 ? GL_RGBA32F : GL_RGB32F, width, height);
    glBindTexture(GL_TEXTURE_2D, source_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, channels == 4 ? GL_RGBA : GL_RGB, GL_FLOAT, pixels);
    width_ = width;
    height_ = height;
    sourceChannels_ = channels;
    sceneLinear_ = stale_ = true;
}

void PictureTexture::setDisplay(const ColorConfig& config, const std::string& display, const std::string& view,
                                const DisplayGrade& grade) {
    if (!display_ || config.file() != configFile_ || display != display_->display() || view != display_->view()) {
        display_ = std::make_unique<OcioDisplayProgram>(config, display, view);
        configFile_ = config.file();
        stale_ = sceneLinear_;
    }
    if (!(grade == grade_)) stale_ = sceneLinear_;
    grade_ = grade;
}

void PictureTexture::transform() {
    std::array<int, 4> viewport{};
    glGetIntegerv(GL_VIEWPORT, viewport.data());
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, displayed_, 0);
    glViewport(0, 0, width_, height_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, source_);
    display_->draw(grade_, vertexArray_);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    stale_ = false;
}

void PictureTexture::draw() {
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (empty()) return;
    if (stale_) transform();
    glUseProgram(program_);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, displayed_);
    glUniform1i(glGetUniformLocation(program_, "picture"), 0);
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

Image PictureTexture::displayed() {
    if (empty()) return {};
    if (stale_) transform();
    std::vector<float> rgba(std::size_t(width_) * height_ * 4);
    glBindTexture(GL_TEXTURE_2D, displayed_);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
    Image rgb(width_, height_, 3);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x)
            for (int c = 0; c < 3; ++c) rgb.at(x, y, c) = rgba[(std::size_t(y) * width_ + x) * 4 + c];
    return rgb;
}

}  // namespace opal::view
