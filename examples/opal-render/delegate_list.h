// opal-render --list-delegates: what the plugin registry finds from this program, so that a
// pipeline can see which delegate a render would use and why a plugin is missing.
#pragma once

#include "plugin/plugin_registry.h"

#include <ostream>

namespace opal::render {

// Writes the registry's search paths, its renderer plugins in priority order (type,
// display name, priority, library, manifest) and every manifest or declaration it skipped
// with the reason (the registry's problems, each naming its file).
void listDelegates(const PluginRegistry& registry, std::ostream& out);

}  // namespace opal::render
