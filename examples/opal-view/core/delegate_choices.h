// The delegate picker's contents: every renderer plugin the registry found, in its
// priority order (the order the default is chosen in), the one in use marked. The viewer's
// panel draws these; the script action `delegates` prints plugin/plugin_listing.h's listing
// (as opal-render --list-delegates does, a line per plugin), and an unknown type fails with
// the registry's requireRendererPlugin message.
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

}  // namespace opal::view
