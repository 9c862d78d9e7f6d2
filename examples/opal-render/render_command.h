// One opal-render run, stage by stage: load the scene (and its assets), create the render
// delegate through the plugin registry, populate and sync a render index, render the
// AOVs through the chosen camera, and write the EXR (and preview).
#pragma once

#include "examples/opal-render/render_options.h"

#include <ostream>
#include <string>

namespace opal::render {

// Runs `options`; warnings go to `warnings`, one per line. Returns the one-line summary
// (output, resolution, camera, delegate, time per stage). Throws opal::Error; no output
// file is written then.
std::string renderScene(const RenderOptions& options, std::ostream& warnings);

}  // namespace opal::render
