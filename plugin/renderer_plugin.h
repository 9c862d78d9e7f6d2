// What a renderer plugin library provides (Hydra's HdRendererPlugin): a named factory of
// render delegates. Hosts never name the concrete class; they find the plugin through a
// PluginRegistry, which reads the library's plugInfo.json and calls its factory.
//
// The factory convention: for each type the manifest declares under Info.Types with
// "HdRendererPlugin" among its "bases", the library exports an extern "C" function
//
//     opal::RendererPlugin* <symbol>();
//
// returning a new plugin that the registry owns (and deletes before it unloads the
// library). <symbol> is the type entry's "factory" string if it has one, else
// "<TypeName>_create". OPAL_RENDERER_PLUGIN_FACTORY writes the default declaration:
//
//     OPAL_RENDERER_PLUGIN_FACTORY(OpalRendererPlugin) { return new opal::OpalRendererPlugin; }
#pragma once

#include "delegate/hd/render_delegate.h"

#include <map>
#include <memory>
#include <string>

namespace opal {

class RendererPlugin {
public:
    virtual ~RendererPlugin() = default;

    // The name menus show (the manifest's displayName says the same before loading).
    virtual std::string displayName() const = 0;
    // Whether the renderer can run here (hardware, licences, ...); the registry's
    // default is the first supported plugin in priority order.
    virtual bool isSupported() const = 0;
    // A new render delegate with `settings` applied ("opal:..." names, as
    // hd::RenderDelegate::setRenderSetting). Throws opal::Error for a bad setting.
    virtual std::unique_ptr<hd::RenderDelegate> createRenderDelegate(const std::map<hd::Token, hd::Value>& settings) = 0;
};

// The signature of a plugin library's factory function.
using RendererPluginFactory = RendererPlugin*();

}  // namespace opal

// Defines the default factory of the manifest type `TypeName`: TypeName_create.
#define OPAL_RENDERER_PLUGIN_FACTORY(TypeName) OPAL_RENDERER_PLUGIN_FACTORY_NAMED(TypeName##_create)
// Defines a factory named by a manifest's "factory" key.
#define OPAL_RENDERER_PLUGIN_FACTORY_NAMED(symbol) \
    extern "C" __attribute__((visibility("default"))) ::opal::RendererPlugin* symbol()
