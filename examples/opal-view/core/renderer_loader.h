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
    RenderDelegateHandle delegate;  // last: goes before the plugin it came from
};

// The registry this program searches; what it skipped goes to `warnings`, one line each.
PluginRegistry hostRegistry(std::ostream& warnings);

// `typeName`: one of the registry's renderer plugin types (an unknown one throws the
// registry's opal::Error listing those there are), else the
// registry's default. Throws opal::Error when the plugin does not load.
LoadedRenderer loadRenderer(const PluginRegistry& registry, const std::optional<std::string>& typeName);

}  // namespace opal::view
