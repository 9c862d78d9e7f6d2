// Owning handles to what a plugin library created (Hydra's HdRendererPluginHandle and
// HdPluginRenderDelegateUniqueHandle). Each keeps the library loaded for as long as it
// lives and destroys its object before letting the library go.
//
// A render delegate's prims and render passes also run the library's code: destroy them
// (the RenderIndex, every RenderPass) before the RenderDelegateHandle, as Hydra hosts do.
#pragma once

#include "plugin/renderer_plugin.h"
#include "plugin/renderer_plugin_info.h"
#include "plugin/shared_library.h"

#include <map>
#include <memory>

namespace opal {

class RenderDelegateHandle;

class RendererPluginHandle {
public:
    // Takes ownership of `plugin`, which `library` created. Copies share the plugin.
    RendererPluginHandle(RendererPluginInfo info, std::unique_ptr<RendererPlugin> plugin,
                         std::shared_ptr<SharedLibrary> library);

    const RendererPluginInfo& info() const { return info_; }
    RendererPlugin& plugin() const { return *plugin_; }
    RendererPlugin* operator->() const { return plugin_.get(); }

    // A new render delegate; throws opal::Error if the plugin returns none (or throws
    // its own error for a bad setting).
    RenderDelegateHandle createRenderDelegate(const std::map<hd::Token, hd::Value>& settings = {}) const;

private:
    RendererPluginInfo info_;
    std::shared_ptr<RendererPlugin> plugin_;  // its deleter holds the library
};

class RenderDelegateHandle {
public:
    RenderDelegateHandle(std::shared_ptr<RendererPlugin> plugin, std::unique_ptr<hd::RenderDelegate> delegate)
        : plugin_(std::move(plugin)), delegate_(std::move(delegate)) {}
    RenderDelegateHandle(RenderDelegateHandle&&) = default;
    // The old delegate goes before the old plugin (and library) it came from.
    RenderDelegateHandle& operator=(RenderDelegateHandle&& other) noexcept {
        delegate_ = std::move(other.delegate_);
        plugin_ = std::move(other.plugin_);
        return *this;
    }
    ~RenderDelegateHandle() { delegate_.reset(); }

    hd::RenderDelegate& operator*() const { return *delegate_; }
    hd::RenderDelegate* operator->() const { return delegate_.get(); }
    hd::RenderDelegate* get() const { return delegate_.get(); }

private:
    std::shared_ptr<RendererPlugin> plugin_;       // declared first: destroyed last
    std::unique_ptr<hd::RenderDelegate> delegate_;
};

}  // namespace opal
