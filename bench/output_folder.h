// The folder a benchmark writes its results into (the files themselves are written with
// opal::writeFileAtomically and opal::writeAtomically, schema/usd/atomic_file.h).
#pragma once

#include <filesystem>

namespace opal::bench {

// Creates dir (and parents) if needed; throws std::runtime_error naming it on failure.
void ensureDirectory(const std::filesystem::path& dir);

}  // namespace opal::bench
