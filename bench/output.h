// Writing benchmark results: every file is written to a temporary name beside its
// destination and renamed, so a crash never leaves a half-written result.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace opal::bench {

// Creates dir (and parents) if needed; throws std::runtime_error naming it on failure.
void ensureDirectory(const std::filesystem::path& dir);

// Writes text to path via a temporary sibling, fsync and a rename. Throws
// std::runtime_error naming the file and the cause (e.g. "No space left on device") on
// failure; the previous file at path is then intact and the temporary removed.
void writeTextAtomically(const std::filesystem::path& path, std::string_view text);

// Calls write(temporary) with a temporary sibling that keeps path's extension (image
// writers pick the format from it), then renames it to path. write returns false or
// throws on failure; either way the temporary is removed, the previous file is intact and
// std::runtime_error names the file and what write threw.
void writeFileAtomically(const std::filesystem::path& path,
                         const std::function<bool(const std::filesystem::path&)>& write);

}  // namespace opal::bench
