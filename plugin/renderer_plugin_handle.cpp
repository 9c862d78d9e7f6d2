#include "plugin/renderer_plugin_handle.h"

#include "schema/error.h"

namespace opal {

RendererPluginHandle::RendererPluginHandle(RendererPluginInfo info, std::unique_ptr<RendererPlugin> plugin,
                                           std::shared_ptr<SharedLibrary> library)
    : info_(std::move(info)),
      // The deleter owns the library: the plugin is deleted by its own code, then the
      // library is released with the deleter.
      plugin_(plugin.release(), [library = std::move(library)](RendererPlugin* p) { delete p; }) {}

RenderDelegateHandle RendererPluginHandle::createRenderDelegate(const std::map<hd::Token, hd::Value>& settings) const {
    std::unique_ptr<hd::RenderDelegate> delegate = plugin_->createRenderDelegate(settings);
    if (!delegate)
        throw Error("renderer plugin '" + info_.typeName + "' (" + info_.libraryPath.string() +
                    ") created no render delegate");
    return RenderDelegateHandle(plugin_, std::move(delegate));
}

}  // namespace opal
