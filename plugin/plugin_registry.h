// The registry hosts use to find and create renderer plugins (USD's PlugRegistry and
// HdRendererPluginRegistry in one object). The host creates it with its search paths;
// nothing is global. It reads every plugInfo.json the paths lead to (following Includes)
// when constructed, and loads a plugin's library only when a plugin is created.
//
// A renderer plugin is a type in a manifest's Info.Types whose "bases" include
// "HdRendererPlugin", with a "displayName" string and an integer "priority", and
// optionally a "factory" symbol name (renderer_plugin.h gives the factory convention).
//
// Order and precedence, as in Hydra: plugins are listed by priority, smaller numbers
// first (hdStorm is 0, hdEmbree 99), ties by type name; the default is the first one
// that isSupported(). When two manifests declare the same type name, the first one read
// wins (search paths are read in order, so $OPAL_PLUGINPATH can override shipped
// plugins) and the other is reported in problems().
//
// A bad manifest never stops the host: discovery keeps going and records each problem
// (missing file, JSON syntax error with line:column, missing or mistyped key, duplicate
// type) in problems(), naming the file. Creating a plugin throws opal::Error for a
// library that is missing or will not load (dlerror's text), a missing factory symbol, a
// factory that throws or returns null. Not thread-safe.
#pragma once

#include "plugin/plugin_manifest.h"
#include "plugin/renderer_plugin_handle.h"
#include "plugin/renderer_plugin_info.h"

#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace opal {

class PluginRegistry {
public:
    // Each search path is a plugInfo.json file or a directory holding one.
    explicit PluginRegistry(std::vector<std::filesystem::path> searchPaths);

    const std::vector<std::filesystem::path>& searchPaths() const { return searchPaths_; }
    // Every manifest read successfully, in reading order.
    const std::vector<std::filesystem::path>& manifests() const { return manifests_; }
    // What was skipped or ignored while reading manifests, and why (each names its file).
    const std::vector<std::string>& problems() const { return problems_; }

    // In priority order (smaller first), then by type name.
    const std::vector<RendererPluginInfo>& rendererPlugins() const { return renderers_; }
    // nullptr if no manifest declares `typeName`.
    const RendererPluginInfo* findRendererPlugin(std::string_view typeName) const;
    // The plugin of that type; throws opal::Error otherwise: "no renderer plugin 'X'
    // (available: DISPLAY NAME (TYPE, priority N), ...; search paths: A:B)", then the
    // problems while reading manifests, if any.
    const RendererPluginInfo& requireRendererPlugin(std::string_view typeName) const;

    // Loads the type's library and calls its factory; throws opal::Error (for an unknown
    // type, requireRendererPlugin's).
    RendererPluginHandle createRendererPlugin(std::string_view typeName) const;
    // The first plugin in priority order that loads and isSupported(); throws opal::Error
    // listing why each candidate was passed over if there is none.
    RendererPluginHandle defaultRendererPlugin() const;

private:
    void readSearchPath(const std::filesystem::path& path);
    void readManifest(const std::filesystem::path& file);
    void addRendererTypes(const PluginManifest& manifest, const PluginEntry& plugin);
    void addRenderer(RendererPluginInfo info, const std::string& location);
    RendererPluginHandle create(const RendererPluginInfo& info) const;
    std::string noPluginMessage(std::string_view typeName) const;

    std::vector<std::filesystem::path> searchPaths_;
    std::vector<std::filesystem::path> manifests_;
    std::set<std::filesystem::path> visited_;
    std::vector<std::string> problems_;
    std::vector<RendererPluginInfo> renderers_;
};

}  // namespace opal
