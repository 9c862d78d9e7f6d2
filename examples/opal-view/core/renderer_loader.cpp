#include "examples/opal-view/core/renderer_loader.h"

#include "plugin/search_paths.h"

namespace opal::view {

LoadedRenderer loadRenderer(const std::optional<std::string>& typeName, std::ostream& warnings) {
    const PluginRegistry registry(hostSearchPaths(executablePath()));
    for (const std::string& problem : registry.problems()) warnings << "opal-view: warning: " << problem << '\n';
    RendererPluginHandle plugin = typeName ? registry.createRendererPlugin(*typeName) : registry.defaultRendererPlugin();
    RenderDelegateHandle delegate = plugin.createRenderDelegate();
    return {std::move(plugin), std::move(delegate)};
}

}  // namespace opal::view
