#include "examples/opal-render/frame_files.h"

#include "delegate/output/preview_writer.h"
#include "schema/error.h"
#include "schema/usd/atomic_file.h"

#include <algorithm>
#include <cctype>

namespace opal::render {
namespace {

std::string lowerExtension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

}  // namespace

void checkFrameFiles(const FrameFiles& files) {
    if (lowerExtension(files.exr) != ".exr")
        throw Error("output '" + files.exr.string() + "': opal-render writes OpenEXR, expected a .exr file name");
    if (files.preview) {
        const std::string extension = lowerExtension(*files.preview);
        if (extension != ".png" && extension != ".jpg" && extension != ".jpeg")
            throw Error("preview '" + files.preview->string() + "': expected a .png, .jpg or .jpeg file name");
    }
}

void writeFrameFiles(const FrameFiles& files, const FrameContent& content, std::vector<std::string>* warnings) {
    writeAtomically(files.exr, [&](const std::filesystem::path& temporary) {
        writeExr(temporary, content.layers, content.colorSpace, content.metadata, content.options, warnings);
        if (files.preview) writePreview(*files.preview, content.previewImage.value());
    });
}

}  // namespace opal::render
