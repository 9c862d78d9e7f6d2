// The dome map a bench lights with, read as the delegate reads it (OpenImageIO, then OCIO
// from the UsdLux default texture colour space to the working space).
#pragma once

#include "delegate/relight/environment_light.h"

#include <filesystem>
#include <memory>

namespace opal::bench {

// Throws opal::Error naming the file when it is not there (with how to point at one) or
// cannot be read.
std::shared_ptr<const LatLongMap> readDomeMap(const std::filesystem::path& env);

}  // namespace opal::bench
