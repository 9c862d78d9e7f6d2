// The delegate picker's contents: every renderer plugin the registry found, in its
// priority order (the order the default is chosen in), the one in use marked, and the
// manifests or declarations it skipped with the reason (as opal-render --list-delegates
// prints them). The viewer's panel draws these; the script action `delegates` prints them.
#pragma once

#include "plugin/plugin_registry.h"

#include <string>
#include <string_view>
#include <vector>

namespace opal::view {

struct DelegateChoice {
    std::string typeName;     // what --delegate and the script's `delegate` name
    std::string displayName;
    int priority = 0;
    bool current = false;
};

std::vector<DelegateChoice> delegateChoices(const PluginRegistry& registry, std::string_view current);

// "renderer plugins (by priority, smaller first):", a line per choice ("* " marks the
// current one: "* Opal (OpalRendererPlugin, priority 100)"), then "skipped:" and a line per
// problem (or "skipped: none").
std::string delegateListing(const PluginRegistry& registry, std::string_view current);

// The registry's plugin of that type; throws opal::Error "no renderer plugin 'X'
// (available: DISPLAY NAME (TYPE, priority N), ...)" otherwise, as the picker lists them.
const RendererPluginInfo& requireDelegate(const PluginRegistry& registry, std::string_view typeName);

}  // namespace opal::view
