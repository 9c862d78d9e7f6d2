#include "delegate/output/preview_writer.h"

#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

namespace opal {
namespace {

enum class PreviewFormat { Png, Jpeg };

PreviewFormat formatOf(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".png") return PreviewFormat::Png;
    if (ext == ".jpg" || ext == ".jpeg") return PreviewFormat::Jpeg;
    throw Error(file.string() + ": unsupported preview format '" + ext +
                "'; use .png, .jpg or .jpeg (scene-linear output belongs in .exr)");
}

// The 8-bit pixels to store: unassociated RGBA for PNG with alpha, RGB otherwise.
std::vector<std::uint8_t> quantize(const Image& image, int outChannels) {
    const bool unassociate = outChannels == 4;
    std::vector<std::uint8_t> bytes;
    bytes.reserve(static_cast<std::size_t>(image.width()) * image.height() * outChannels);
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            const float alpha = unassociate ? image.at(x, y, 3) : 1.0f;
            for (int c = 0; c < 3; ++c) {
                bytes.push_back(quantizeToByte(alpha > 0.0f ? image.at(x, y, c) / alpha : 0.0f));
            }
            if (unassociate) bytes.push_back(quantizeToByte(alpha));
        }
    }
    return bytes;
}

void writeBytes(const std::filesystem::path& file, const Image& image, int channels,
                const std::vector<std::uint8_t>& bytes, PreviewFormat format) {
    OIIO::ImageSpec spec(image.width(), image.height(), channels, OIIO::TypeDesc::UINT8);
    if (channels == 4) spec.attribute("oiio:UnassociatedAlpha", 1);  // already unassociated
    if (format == PreviewFormat::Jpeg) spec.attribute("Compression", "jpeg:95");
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(file.string());
    if (!out) throw Error("OpenImageIO cannot write it: " + OIIO::geterror());
    if (!out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, bytes.data()) ||
        !out->close()) {
        throw Error("OpenImageIO: " + out->geterror());
    }
}

}  // namespace

std::uint8_t quantizeToByte(float displayValue) {
    if (!(displayValue > 0.0f)) return 0;  // also NaN
    if (displayValue >= 1.0f) return 255;
    return static_cast<std::uint8_t>(displayValue * 255.0f + 0.5f);
}

void writePreview(const std::filesystem::path& file, const Image& displayReferred) {
    const PreviewFormat format = formatOf(file);
    if (displayReferred.channels() != 3 && displayReferred.channels() != 4) {
        throw Error(file.string() + ": preview needs an RGB or RGBA image, got " +
                    std::to_string(displayReferred.channels()) + " channels");
    }
    const int channels = format == PreviewFormat::Png ? displayReferred.channels() : 3;
    const std::vector<std::uint8_t> bytes = quantize(displayReferred, channels);
    writeAtomically(file, [&](const std::filesystem::path& temporary) {
        writeBytes(temporary, displayReferred, channels, bytes, format);
    });
}

}  // namespace opal
