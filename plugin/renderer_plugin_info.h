// What a manifest says about one renderer plugin type, known before its library loads
// (Hydra's HfPluginDesc plus where it came from), and how it is read from a manifest.
#pragma once

#include "plugin/plugin_manifest.h"

#include <filesystem>
#include <string>

namespace opal {

struct RendererPluginInfo {
    std::string typeName;                // the Info.Types key, e.g. "OpalRendererPlugin"
    std::string displayName;             // "displayName"
    int priority = 0;                    // "priority": smaller ranks first, as in Hydra
    std::string pluginName;              // the plugin's "Name"
    std::filesystem::path libraryPath;   // absolute
    std::filesystem::path manifestPath;  // the plugInfo.json that declared it
    std::string factorySymbol;           // "factory", default "<typeName>_create"
};

// "DISPLAY NAME (TYPE, priority N)": how hosts name a plugin in lists and errors.
std::string describeRendererPlugin(const RendererPluginInfo& info);

// Whether `type` declares a renderer plugin: "HdRendererPlugin" is among its bases.
bool isRendererPluginType(const PluginType& type);

// The renderer plugin `type` of `plugin` in `manifest` declares. Throws opal::Error
// naming the manifest and the type's JSON location if displayName (a non-empty string)
// or priority (an int) is missing or mistyped, if "factory" is not a C identifier (or is
// absent and the type name is not one), or if the plugin has no library.
RendererPluginInfo readRendererPluginInfo(const PluginManifest& manifest, const PluginEntry& plugin,
                                          const PluginType& type);

}  // namespace opal
