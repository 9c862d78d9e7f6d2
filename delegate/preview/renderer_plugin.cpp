// The opalPreview module: the extern "C" factory plugin/'s registry calls
// (plugin/renderer_plugin.h) and the plugin that creates the preview delegate. Registered as
// OpalPreviewRendererPlugin, display name "Opal Preview", priority 200: after Opal (100),
// so it is never the default where Opal runs (delegate/preview/CMakeLists.txt).
#include "delegate/preview/preview_delegate.h"
#include "plugin/renderer_plugin.h"
#include "raytrace/embree_device_config.h"

namespace opal::preview {

class PreviewRendererPlugin final : public RendererPlugin {
public:
    std::string displayName() const override { return "Opal Preview"; }

    // It needs an Embree device, as Opal does.
    bool isSupported() const override { return embreeDeviceAvailable(); }

    std::unique_ptr<hd::RenderDelegate> createRenderDelegate(const std::map<hd::Token, hd::Value>& settings) override {
        return std::make_unique<PreviewRenderDelegate>(settings);
    }
};

}  // namespace opal::preview

OPAL_RENDERER_PLUGIN_FACTORY(OpalPreviewRendererPlugin) { return new opal::preview::PreviewRendererPlugin; }
