// Replacing a file atomically: write a temporary file beside it, fsync, rename. A crash
// leaves either the old file or the new one, never a half-written one.
#pragma once

#include <filesystem>
#include <string_view>

namespace opal {

// Throws opal::Error naming `path` and the system error.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace opal
