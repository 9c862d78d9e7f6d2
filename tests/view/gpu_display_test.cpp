// The window's picture through OCIO's display transform on the GPU (gl/picture_texture.h)
// against the CPU transform of the same scene-linear picture (DisplayPicture, what a saved
// PNG holds): saturated ACEScg colours, some outside sRGB's gamut, from 1/256 to 64, through
// the ACES 1.0 SDR view, with exposure and gamma. Truth: the 8-bit codes of the CPU
// values; the window's codes may differ by at most 1 (float rounding on either side of a
// code's boundary). A pass-through or a wrong transform is off by tens of codes.
#include "examples/opal-view/core/display_picture.h"
#include "examples/opal-view/gl/picture_texture.h"

#include <glad/gl.h>
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace opal::view {
namespace {

constexpr const char* AcesView = "ACES 1.0 - SDR Video";

// Hue around the colour wheel across, intensity up the picture, RGBA with an alpha that
// must be ignored.
Image saturatedPicture(int width, int height) {
    Image image(width, height, 4);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float intensity = std::exp2(-8.0f + 14.0f * float(y) / float(height - 1));
            const float hue = 6.0f * float(x) / float(width);
            const int sector = int(hue) % 6;
            const float f = hue - std::floor(hue);
            // Fully saturated: one channel 0, one 1 and the third ramping, as an HSV wheel.
            const float ramps[6][3] = {{1, f, 0}, {1 - f, 1, 0}, {0, 1, f}, {0, 1 - f, 1}, {f, 0, 1}, {1, 0, 1 - f}};
            for (int c = 0; c < 3; ++c) image.at(x, y, c) = intensity * ramps[sector][c];
            image.at(x, y, 3) = float(x % 3) / 2.0f;
        }
    return image;
}

struct GlWindow {
    GLFWwindow* window = nullptr;
    int width = 0, height = 0;
    std::string error;  // GLFW's reason when there is no window

    GlWindow(int w, int h) {
        if (!glfwInit()) {
            noteError();
            return;
        }
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
        window = glfwCreateWindow(w, h, "gpu display test", nullptr, nullptr);
        if (!window) {
            noteError();
            return;
        }
        glfwMakeContextCurrent(window);
        if (!gladLoadGL(glfwGetProcAddress)) {
            glfwDestroyWindow(window);
            window = nullptr;
            error = "glad could not load OpenGL's functions";
            return;
        }
        glfwGetFramebufferSize(window, &width, &height);
    }
    ~GlWindow() {
        if (window) glfwDestroyWindow(window);
        glfwTerminate();
    }

    void noteError() {
        const char* description = nullptr;
        const int code = glfwGetError(&description);
        error = "GLFW error " + std::to_string(code) + ": " + (description ? description : "none");
    }

    // The back buffer's RGB codes, row 0 at the top.
    std::vector<std::uint8_t> pixels() const {
        std::vector<std::uint8_t> bytes(std::size_t(width) * height * 3), top(bytes.size());
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
        const std::size_t row = std::size_t(width) * 3;
        for (int y = 0; y < height; ++y)
            std::copy_n(bytes.begin() + std::ptrdiff_t(std::size_t(height - 1 - y) * row), row,
                        top.begin() + std::ptrdiff_t(std::size_t(y) * row));
        return top;
    }
};

int code(float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

TEST(GpuDisplay, TheWindowShowsTheCpuTransformOfTheSceneLinearPicture) {
    const GlWindow gl(96, 64);
    ASSERT_NE(gl.window, nullptr) << "no OpenGL 3.3 core window (the view tests run under xvfb-run): " << gl.error;
    const ColorConfig config = ColorConfig::fromEnvironment();
    const std::string display = config.defaultDisplay();
    const Image linear = saturatedPicture(gl.width, gl.height);
    DisplayPicture cpu(config);
    cpu.setDisplayView(display, AcesView);
    PictureTexture picture;
    for (const DisplayGrade grade : {DisplayGrade{0.0, 1.0}, DisplayGrade{1.5, 1.0}, DisplayGrade{-1.0, 2.2}}) {
        picture.setDisplay(config, display, AcesView, grade);
        picture.uploadSceneLinear(linear.pixels().data(), linear.width(), linear.height(), linear.channels());
        glViewport(0, 0, gl.width, gl.height);
        picture.draw();
        const std::vector<std::uint8_t> shown = gl.pixels();
        const Image truth = cpu.toDisplay(linear, "color", grade);
        const Image drawn = picture.displayed();
        int worst = 0, saturated = 0, varied = 0;
        double worstValue = 0.0;
        for (int y = 0; y < gl.height; ++y)
            for (int x = 0; x < gl.width; ++x) {
                int lo = 255, hi = 0;
                for (int c = 0; c < 3; ++c) {
                    const int expected = code(truth.at(x, y, c));
                    const int got = shown[(std::size_t(y) * gl.width + x) * 3 + c];
                    worst = std::max(worst, std::abs(got - expected));
                    worstValue = std::max(worstValue, double(std::abs(drawn.at(x, y, c) - truth.at(x, y, c))));
                    lo = std::min(lo, expected);
                    hi = std::max(hi, expected);
                    // What a pass-through (the grade alone, no view) would show.
                    const double graded = std::pow(std::max(0.0, linear.at(x, y, c) * std::exp2(grade.exposure)), 1.0 / grade.gamma);
                    varied += std::abs(code(float(graded)) - expected) > 2;
                }
                saturated += hi - lo > 128;
            }
        EXPECT_LE(worst, 1) << "8-bit codes off, exposure " << grade.exposure << ", gamma " << grade.gamma;
        EXPECT_LT(worstValue, 2e-3) << "display-referred values off, exposure " << grade.exposure;
        EXPECT_GT(saturated, gl.width * gl.height / 8) << "the picture holds saturated colours";
        EXPECT_GT(varied, gl.width * gl.height) << "the view changes a third of the codes: it is not a pass-through";
        std::printf("ACES view on the GPU, exposure %+.1f, gamma %.1f: worst %d code(s), %.2e in value\n",
                    grade.exposure, grade.gamma, worst, worstValue);
    }
}

TEST(GpuDisplay, AnUnknownViewIsRefusedNamingIt) {
    const GlWindow gl(32, 32);
    ASSERT_NE(gl.window, nullptr) << gl.error;
    PictureTexture picture;
    const ColorConfig config = ColorConfig::fromEnvironment();
    try {
        picture.setDisplay(config, config.defaultDisplay(), "No Such View", {});
        FAIL() << "accepted an unknown view";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("No Such View"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace opal::view
