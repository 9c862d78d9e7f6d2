// The opalDelegate module (Hydra's rendererPlugin): the extern "C" factory that plugin/'s
// registry calls (plugin/renderer_plugin.h) and the plugin that creates Opal's render
// delegate. Registered as OpalRendererPlugin, display name "Opal", priority 100
// (delegate/CMakeLists.txt, opal_add_renderer_plugin).
#include "delegate/render_delegate.h"
#include "plugin/renderer_plugin.h"
#include "raytrace/embree_device_config.h"

namespace opal {

class OpalRendererPlugin final : public RendererPlugin {
public:
    std::string displayName() const override { return "Opal"; }

    // Opal needs an Embree device (a CPU with SSE2 at least, which Embree checks).
    bool isSupported() const override { return embreeDeviceAvailable(); }

    std::unique_ptr<hd::RenderDelegate> createRenderDelegate(const std::map<hd::Token, hd::Value>& settings) override {
        return std::make_unique<OpalRenderDelegate>(settings);
    }
};

}  // namespace opal

OPAL_RENDERER_PLUGIN_FACTORY(OpalRendererPlugin) { return new opal::OpalRendererPlugin; }
