// The files a render ends in: the scene-linear multi-layer EXR for compositing and, on
// request, an 8-bit display-referred preview. They are written only after the render
// succeeded, and together: the EXR goes to a temporary file, the preview is written
// (atomically), then the EXR is renamed into place, so a failure leaves no new EXR.
#pragma once

#include "delegate/output/aov_layer.h"
#include "delegate/output/display_transform.h"
#include "delegate/output/exr_writer.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace opal::render {

struct FrameFiles {
    std::filesystem::path exr;
    std::optional<std::filesystem::path> preview;
};

// Throws opal::Error unless the EXR path ends in .exr and the preview's in .png, .jpg or
// .jpeg: checked before rendering, so a run that cannot write its files does no work.
void checkFrameFiles(const FrameFiles& files);

struct FrameContent {
    std::vector<AovLayer> layers;         // the EXR's
    ColorSpaceIdentity colorSpace;        // the working space
    ExrMetadata metadata;
    ExrOptions options;
    std::optional<Image> previewImage;    // display-referred, when a preview is asked for
};

// Throws opal::Error naming the file that could not be written.
void writeFrameFiles(const FrameFiles& files, const FrameContent& content, std::vector<std::string>* warnings);

}  // namespace opal::render
