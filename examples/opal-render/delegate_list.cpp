#include "examples/opal-render/delegate_list.h"

namespace opal::render {

void listDelegates(const PluginRegistry& registry, std::ostream& out) {
    out << "search paths:" << (registry.searchPaths().empty() ? " none\n" : "\n");
    for (const std::filesystem::path& path : registry.searchPaths()) out << "  " << path.string() << '\n';

    // Priority order is the order a default is chosen in (the first that is supported).
    out << "renderer plugins (by priority, smaller first):" << (registry.rendererPlugins().empty() ? " none\n" : "\n");
    for (const RendererPluginInfo& plugin : registry.rendererPlugins()) {
        out << "  " << plugin.typeName << '\n'
            << "    display name: " << plugin.displayName << '\n'
            << "    priority: " << plugin.priority << '\n'
            << "    library: " << plugin.libraryPath.string() << '\n'
            << "    manifest: " << plugin.manifestPath.string() << '\n';
    }

    out << "skipped:" << (registry.problems().empty() ? " none\n" : "\n");
    for (const std::string& problem : registry.problems()) out << "  " << problem << '\n';
}

}  // namespace opal::render
