#include "examples/opal-view/core/delegate_choices.h"

namespace opal::view {

std::vector<DelegateChoice> delegateChoices(const PluginRegistry& registry, std::string_view current) {
    std::vector<DelegateChoice> choices;
    for (const RendererPluginInfo& plugin : registry.rendererPlugins())
        choices.push_back({plugin.typeName, plugin.displayName, plugin.priority, plugin.typeName == current});
    return choices;
}

}  // namespace opal::view
