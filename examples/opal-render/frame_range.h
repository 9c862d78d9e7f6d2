// opal-render --frames START:END [--step S]: a range of USD time codes, and the numbered
// file names a sequence is written to (OUT.exr -> OUT.0001.exr, frame padded to 4 digits,
// as compositing packages expect).
#pragma once

#include "examples/opal-render/render_options.h"

#include <filesystem>
#include <string_view>
#include <vector>

namespace opal::render {

// "START:END" with integers START <= END, step >= 1, at most 100,000 frames. Throws
// opal::Error naming --frames or --step and the problem.
RenderOptions::Frames parseFrameRange(std::string_view text, int step);

// START, START + step, ... up to END.
std::vector<int> framesOf(const RenderOptions::Frames& frames);

// `file` with ".NNNN" before its extension.
std::filesystem::path numberedPath(const std::filesystem::path& file, int frame);

}  // namespace opal::render
