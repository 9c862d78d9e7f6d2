#include "bench/error_image.h"

#include "schema/error.h"
#include "schema/scatter/rgb.h"  // kAcescgLuminance

#include <algorithm>
#include <cmath>
#include <string>

namespace opal::bench {

Image luminanceErrorImage(int width, int height, std::span<const float> engine, std::span<const float> reference,
                          std::span<const std::uint8_t> mask) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    if (mask.size() != pixels || engine.size() != 3 * pixels || reference.size() != 3 * pixels)
        throw Error("error image: " + std::to_string(width) + "x" + std::to_string(height) + " does not match " +
                    std::to_string(mask.size()) + " mask pixels and " + std::to_string(engine.size()) + " / " +
                    std::to_string(reference.size()) + " values");
    Image image(width, height, 3);
    for (std::size_t p = 0; p < pixels; ++p) {
        float* out = image.pixels().data() + 3 * p;
        if (!mask[p]) {
            out[0] = 0.05f, out[1] = 0.1f, out[2] = 0.3f;
            continue;
        }
        double ya = 0.0, yb = 0.0;
        for (int c = 0; c < 3; ++c) {
            ya += kAcescgLuminance[c] * engine[3 * p + c];
            yb += kAcescgLuminance[c] * reference[3 * p + c];
        }
        const float grey = yb > 0.0 ? float(std::min(1.0, std::abs(ya - yb) / yb / 0.05)) : 1.0f;
        out[0] = out[1] = out[2] = grey;
    }
    return image;
}

}  // namespace opal::bench
