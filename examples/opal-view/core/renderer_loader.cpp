#include "examples/opal-view/core/renderer_loader.h"

#include "plugin/search_paths.h"

namespace opal::view {

PluginRegistry hostRegistry(std::ostream& warnings) {
    PluginRegistry registry(hostSearchPaths(executablePath()));
    for (const std::string& problem : registry.problems()) warnings << "opal-view: warning: " << problem << '\n';
    return registry;
}

LoadedRenderer loadRenderer(const PluginRegistry& registry, const std::optional<std::string>& typeName) {
    RendererPluginHandle plugin = typeName ? registry.createRendererPlugin(*typeName)
                                           : registry.defaultRendererPlugin();
    RenderDelegateHandle delegate = plugin.createRenderDelegate();
    return {std::move(plugin), std::move(delegate)};
}

}  // namespace opal::view
