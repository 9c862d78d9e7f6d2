// The window's pixels as the user sees them (picture and interface), saved as a PNG.
#pragma once

#include <filesystem>

namespace opal::view {

// Reads the back buffer of the current context (call after drawing, before the swap).
// Throws opal::Error naming the file when it cannot be written.
void saveScreenshot(const std::filesystem::path& file, int width, int height);

}  // namespace opal::view
