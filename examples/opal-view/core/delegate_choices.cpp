#include "examples/opal-view/core/delegate_choices.h"

#include "schema/error.h"

namespace opal::view {
namespace {

std::string describe(const DelegateChoice& choice) {
    return choice.displayName + " (" + choice.typeName + ", priority " + std::to_string(choice.priority) + ")";
}

}  // namespace

std::vector<DelegateChoice> delegateChoices(const PluginRegistry& registry, std::string_view current) {
    std::vector<DelegateChoice> choices;
    for (const RendererPluginInfo& plugin : registry.rendererPlugins())
        choices.push_back({plugin.typeName, plugin.displayName, plugin.priority, plugin.typeName == current});
    return choices;
}

std::string delegateListing(const PluginRegistry& registry, std::string_view current) {
    const std::vector<DelegateChoice> choices = delegateChoices(registry, current);
    std::string text = "renderer plugins (by priority, smaller first):" + std::string(choices.empty() ? " none\n" : "\n");
    for (const DelegateChoice& choice : choices) text += (choice.current ? "* " : "  ") + describe(choice) + "\n";
    text += "skipped:" + std::string(registry.problems().empty() ? " none\n" : "\n");
    for (const std::string& problem : registry.problems()) text += "  " + problem + "\n";
    return text;
}

const RendererPluginInfo& requireDelegate(const PluginRegistry& registry, std::string_view typeName) {
    if (const RendererPluginInfo* info = registry.findRendererPlugin(typeName)) return *info;
    std::string available;
    for (const DelegateChoice& choice : delegateChoices(registry, ""))
        available += (available.empty() ? "" : ", ") + describe(choice);
    throw Error("no renderer plugin '" + std::string(typeName) + "' (available: " +
                (available.empty() ? std::string("none found") : available) + ")");
}

}  // namespace opal::view
