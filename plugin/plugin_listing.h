// What hosts print about their plugin registry: opal-render --list-delegates (every detail,
// for a pipeline to see which delegate a render would use and why a plugin is missing) and
// opal-view's delegate picker and script action `delegates` (a line per plugin, the one in
// use marked). Both list the plugins in priority order (the order the default is chosen
// in) and every manifest or declaration the registry skipped, with the reason.
#pragma once

#include "plugin/plugin_registry.h"

#include <string>
#include <string_view>

namespace opal {

struct PluginListingStyle {
    // The plugin in use, marked "* " (the others "  "); empty marks none.
    std::string_view current;
    // The search paths first, and each plugin as its type name with its display name,
    // priority, library and manifest on lines of their own; else a line per plugin,
    // describeRendererPlugin's "Opal (OpalRendererPlugin, priority 100)".
    bool details = false;
};

// ["search paths:" and a line per path, when detailed,] "renderer plugins (by priority,
// smaller first):" and the plugins, then "skipped:" and a line per registry problem (each
// naming its file). An empty section reads " none" after its title.
std::string pluginListing(const PluginRegistry& registry, const PluginListingStyle& style);

}  // namespace opal
