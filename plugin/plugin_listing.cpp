#include "plugin/plugin_listing.h"

namespace opal {
namespace {

std::string title(const char* name, bool empty) { return std::string(name) + (empty ? " none\n" : "\n"); }

std::string plugin(const RendererPluginInfo& info, const PluginListingStyle& style) {
    const std::string marker = !style.current.empty() && info.typeName == style.current ? "* " : "  ";
    if (!style.details) return marker + describeRendererPlugin(info) + "\n";
    return marker + info.typeName + "\n    display name: " + info.displayName + "\n    priority: " +
           std::to_string(info.priority) + "\n    library: " + info.libraryPath.string() +
           "\n    manifest: " + info.manifestPath.string() + "\n";
}

}  // namespace

std::string pluginListing(const PluginRegistry& registry, const PluginListingStyle& style) {
    std::string text;
    if (style.details) {
        text += title("search paths:", registry.searchPaths().empty());
        for (const std::filesystem::path& path : registry.searchPaths()) text += "  " + path.string() + "\n";
    }
    text += title("renderer plugins (by priority, smaller first):", registry.rendererPlugins().empty());
    for (const RendererPluginInfo& info : registry.rendererPlugins()) text += plugin(info, style);
    text += title("skipped:", registry.problems().empty());
    for (const std::string& problem : registry.problems()) text += "  " + problem + "\n";
    return text;
}

}  // namespace opal
