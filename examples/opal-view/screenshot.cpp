#include "examples/opal-view/screenshot.h"

#include "delegate/output/image.h"
#include "delegate/output/preview_writer.h"

#include <glad/gl.h>

#include <cstdint>
#include <vector>

namespace opal::view {

void saveScreenshot(const std::filesystem::path& file, int width, int height) {
    std::vector<std::uint8_t> bytes(std::size_t(width) * height * 3);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bytes.data());
    // OpenGL's row 0 is the bottom one; the file's is the top one. 8-bit codes go through
    // the preview writer unchanged (it rounds code / 255 back to the code).
    Image image(width, height, 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                image.at(x, y, c) = bytes[(std::size_t(height - 1 - y) * width + x) * 3 + c] / 255.0f;
    writePreview(file, image);
}

}  // namespace opal::view
