// The render delegate, reached only through the plugin registry (as opal-render does):
// $OPAL_PLUGINPATH's folders, then the ones next to the executable.
#pragma once

#include "plugin/plugin_registry.h"

#include <optional>
#include <ostream>
#include <string>

namespace opal::view {

struct LoadedRenderer {
    RendererPluginHandle plugin;
    RenderDelegateHandle delegate;
};

// `typeName`: a renderer plugin type, else the registry's default. What the registry
// skipped goes to `warnings`, one line each. Throws opal::Error when no plugin loads.
LoadedRenderer loadRenderer(const std::optional<std::string>& typeName, std::ostream& warnings);

}  // namespace opal::view
