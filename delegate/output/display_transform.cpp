#include "delegate/output/display_transform.h"

#include "schema/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <utility>

namespace opal {
namespace {

// Rows per task: large enough that OCIO's per-call setup is negligible.
constexpr int kRowsPerTask = 16;

// A block of rows of an RGB or RGBA float image, seen as RGB: with RGBA the pixel stride
// skips alpha, so OCIO never reads or writes it.
OCIO::PackedImageDesc rgbRows(Image& image, int firstRow, int rowCount) {
    const ptrdiff_t channelBytes = sizeof(float);
    const ptrdiff_t pixelBytes = channelBytes * image.channels();
    return OCIO::PackedImageDesc(image.row(firstRow), image.width(), rowCount,
                                 OCIO::CHANNEL_ORDERING_RGB, OCIO::BIT_DEPTH_F32, channelBytes,
                                 pixelBytes, pixelBytes * image.width());
}

}  // namespace

DisplayTransform::DisplayTransform(const ColorConfig& config, std::string display, std::string view)
    : display_(std::move(display)), view_(std::move(view)) {
    processor_ = config.workingToDisplay(display_, view_)->getDefaultCPUProcessor();
}

DisplayTransform::DisplayTransform(const ColorConfig& config)
    : DisplayTransform(config, config.defaultDisplay(),
                       config.defaultView(config.defaultDisplay())) {}

Image DisplayTransform::apply(const Image& sceneLinear) const {
    Image display = sceneLinear;
    applyInPlace(display);
    return display;
}

void DisplayTransform::applyInPlace(Image& image) const {
    if (image.channels() != 3 && image.channels() != 4) {
        throw Error("display transform '" + display_ + "' / '" + view_ + "': image has " +
                    std::to_string(image.channels()) + " channels, expected RGB or RGBA");
    }
    tbb::parallel_for(tbb::blocked_range<int>(0, image.height(), kRowsPerTask),
                      [&](const tbb::blocked_range<int>& rows) {
                          OCIO::PackedImageDesc block =
                              rgbRows(image, rows.begin(), static_cast<int>(rows.size()));
                          processor_->apply(block);
                      });
}

}  // namespace opal
