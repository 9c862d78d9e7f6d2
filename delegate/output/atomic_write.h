// Writing a file so that readers only ever see the old file or the complete new one: the
// data goes to a temporary file in the target's directory (same file system), is flushed
// to disk, then renamed over the target.
#pragma once

#include <filesystem>
#include <functional>

namespace opal {

// Calls `writeTemporary` with the path of a fresh, empty temporary file next to `target`
// whose name ends in target's extension (image libraries pick the format by extension),
// then renames it to `target`. If `writeTemporary` throws, or any step fails, the
// temporary is removed, `target` is left as it was, and opal::Error names `target` and
// the problem.
void writeAtomically(
    const std::filesystem::path& target,
    const std::function<void(const std::filesystem::path& temporary)>& writeTemporary);

}  // namespace opal
